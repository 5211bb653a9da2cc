// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "mrpt_krp_plugin/map/map_sanity.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"

namespace octomap { class OcTree; }

namespace krp {

/// A horizontal band of a 3D OctoMap flattened into a 2D grid: the lidar's height band.
struct OctomapSliceParams {
  double z_min_m = 0.05;  ///< lower edge of the band [m]; below it is floor
  double z_max_m = 0.60;  ///< upper edge of the band [m]; a 2D lidar at ~0.2-0.4 m sees this
  double resolution_m = 0.0;  ///< 2D cell size [m]; 0 = the octree's own resolution
};

/// Slices an in-memory octree: a cell is occupied if any occupied voxel of the band covers
/// it, free if only free voxels do, unknown otherwise.
OccupancyMap sliceOctree(const octomap::OcTree& tree, const OctomapSliceParams& params, const std::string& source,
                         const MapSanityLimits& limits = {});

/// Reads `.bt` (binary) or `.ot` (full) OctoMap files and slices them. Throws InputError.
OccupancyMap readOctomapSlice(const std::string& path, const OctomapSliceParams& params = {},
                              const MapSanityLimits& limits = {});

}  // namespace krp
