// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "mrpt_krp_plugin/map/octomap_slice.h"
#include "mrpt_krp_plugin/map/ros_map_yaml.h"

namespace krp {

struct MapLoadParams {
  MapSanityLimits limits;
  OctomapSliceParams octomap;
};

/// Loads any supported map by its extension: `.yaml`/`.yml` (ROS map_server),
/// `.gridmap`/`.gridmap.gz` (MRPT), `.bt`/`.ot` (OctoMap, sliced). Throws InputError.
OccupancyMap loadOccupancyMap(const std::string& path, const MapLoadParams& params = {});

}  // namespace krp
