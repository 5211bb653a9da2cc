// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>

#include <cstddef>
#include <vector>

#include "mrpt_krp_plugin/sim/rawlog_io.h"

namespace krp {

/// Which scans of a log build a map, and how.
struct LogMapperParams {
  double resolution_m = 0.05;  ///< [m/cell]
  /// Rays are inserted up to this range: far returns of a long-range scanner smear walls
  /// seen at grazing angles. [m]
  double max_insertion_range_m = 30.0;
  double margin_m = 1.0;  ///< extra border around everything the rays reach [m]
  std::size_t first = 0;  ///< the first scan used
  std::size_t every = 1;  ///< then every N-th (2 leaves every other scan out to query it)
};

/// An occupancy grid built with MRPT's ray insertion from the scans of `steps` at the robot
/// poses `poses` (one per step, e.g. a SLAM-corrected log's). No-return beams clear nothing.
/// Throws InputError for mismatched sizes, bad parameters or no scan selected.
mrpt::maps::COccupancyGridMap2D mapFromPosedScans(const std::vector<RawlogStep>& steps,
                                                  const std::vector<mrpt::math::TPose2D>& poses,
                                                  const LogMapperParams& params = {});

}  // namespace krp
