// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "mrpt_krp_plugin/map/map_sanity.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"

namespace krp {

/// The fields of a ROS map_server YAML file, with map_server's defaults.
struct RosMapMetadata {
  std::string image;                ///< image path as written in the YAML
  std::string image_path;           ///< resolved against the YAML's folder
  double resolution = 0.0;          ///< [m/cell]
  double origin_x = 0.0, origin_y = 0.0, origin_yaw = 0.0;  ///< [m, m, rad]
  bool negate = false;
  double occupied_thresh = 0.65;    ///< [0..1]
  double free_thresh = 0.196;       ///< [0..1]
  std::string mode = "trinary";     ///< trinary | scale | raw
};

/// Parses and validates the YAML only (no image read). Throws InputError.
RosMapMetadata readRosMapMetadata(const std::string& yaml_path, const MapSanityLimits& limits = {});

/// Reads a map_server YAML + PGM/PNG map with map_server's semantics. Throws InputError
/// naming the file and the problem for anything it cannot use, including a map with no free cell.
OccupancyMap readRosMap(const std::string& yaml_path, const MapSanityLimits& limits = {});

/// Writes a grid as map_server trinary PGM (0 occupied, 254 free, 205 unknown) + YAML.
/// Both files are written to temporaries and renamed, so a failure leaves nothing half-written.
void writeRosMap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& yaml_path,
                 const CellClassParams& classes = {});

}  // namespace krp
