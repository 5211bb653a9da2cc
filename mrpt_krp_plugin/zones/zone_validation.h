// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>
#include <vector>

#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/zones/zone.h"

namespace krp {

struct ZoneValidationParams {
  double max_overlap_free_m2 = 0.0;  ///< free area two zones may both claim [m^2]
  double min_free_area_m2 = 1.0;     ///< a zone must hold at least this much free space [m^2]
  CellClassParams cells;
};

/// Every problem found, one line each; empty when the zones are valid.
std::vector<std::string> findZoneProblems(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                                          const ZoneValidationParams& params = {});

/// Throws InputError(source, all problems) when any is found.
void validateZones(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                   const std::string& source, const ZoneValidationParams& params = {});

}  // namespace krp
