// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "mrpt_krp_plugin/map/map_sanity.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"

namespace krp {

/// Reads a serialized MRPT `COccupancyGridMap2D` (`.gridmap`, or gzip'ed `.gridmap.gz`).
/// Throws InputError naming the file for a missing, foreign, truncated or empty map, or one
/// outside `limits` (checked before MRPT allocates it).
OccupancyMap readMrptGridmap(const std::string& path, const MapSanityLimits& limits = {});

/// Writes a grid as an MRPT `.gridmap` (gzip'ed when the path ends in `.gz`), atomically.
void writeMrptGridmap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path);

}  // namespace krp
