// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include "mrpt_krp_plugin/common/random.h"

namespace krp {

/// Unmapped objects added to the simulation map only: the localization map never shows
/// them, as in a real building where boxes, pallets and people come and go.
struct ClutterParams {
  double boxes_per_100m2 = 0.8;     ///< boxes per 100 m^2 of free space
  double box_min_side_m = 0.3;      ///< [m]
  double box_max_side_m = 0.8;      ///< [m]
  double pallets_per_100m2 = 0.2;   ///< 1.2 x 0.8 m pallets per 100 m^2
  double people_per_100m2 = 0.4;    ///< people (two legs) per 100 m^2
  double placement_clearance_m = 0.2;  ///< object centres keep this much free space around them [m]
};

/// A copy of `map` with clutter drawn as occupied cells in its free space.
mrpt::maps::COccupancyGridMap2D addClutter(const mrpt::maps::COccupancyGridMap2D& map, const ClutterParams& params,
                                           Rng& rng);

}  // namespace krp
