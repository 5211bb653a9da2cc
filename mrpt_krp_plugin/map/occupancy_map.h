// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>

#include <memory>
#include <string>

namespace krp {

/// A loaded 2D occupancy map. The grid is axis-aligned in the "grid frame"; every pose the
/// library computes is in that frame. `yaw_rad` is the rotation of the grid frame in the
/// frame the map file declared (ROS map_server's origin yaw), so a pose can be reported in
/// the user's map frame with `toSourceFrame`.
struct OccupancyMap {
  std::shared_ptr<mrpt::maps::COccupancyGridMap2D> grid;
  double yaw_rad = 0.0;  ///< grid frame yaw in the source map frame [rad]
  std::string source;    ///< the file it was read from

  /// Grid-frame pose -> the source file's map frame (rotation about the grid origin cell).
  mrpt::math::TPose2D toSourceFrame(const mrpt::math::TPose2D& grid_pose) const;
  /// The inverse: a pose in the source file's map frame -> grid frame.
  mrpt::math::TPose2D toGridFrame(const mrpt::math::TPose2D& source_pose) const;
};

/// p(occupied) of a cell whose state is unknown.
constexpr double kUnknownOccupancy = 0.5;

/// A nav_msgs/OccupancyGrid value as p(occupied): 0..100 are percent, anything else (-1) is
/// unknown. map_server's `raw` image mode stores the same values as pixels.
double occupancyFromGridValue(int value);

/// Thresholds that classify a cell. MRPT stores occupancy as probability of occupation.
struct CellClassParams {
  double max_free_occupancy = 0.35;      ///< a cell with p(occupied) below this is free [0..1]
  double min_occupied_occupancy = 0.65;  ///< a cell with p(occupied) above this is occupied [0..1]
};

/// Number of free cells (for "never a silently empty map" checks and area figures).
std::size_t countFreeCells(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p = {});

/// Free area in m^2.
double freeAreaM2(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p = {});

}  // namespace krp
