// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>

#include <string>
#include <vector>

#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/zones/zone.h"

namespace krp {

/// A zone's reference keypoints: structural points of the global map in grid-frame metres,
/// in a fixed order (keypoint i of the zone's keypoint model is landmark i).
struct ZoneLandmarks {
  std::string zone;
  std::vector<mrpt::math::TPoint2D> points;
};

/// How landmarks are picked (recorded beside them, so a model can say what it was trained on).
struct LandmarkParams {
  int keypoints_per_zone = 12;     ///< K, the same for every zone (the keypoint model's K)
  double search_margin_m = 0.6;    ///< walls this close to a zone's free space count as its own [m]
  double min_spacing_m = 1.0;      ///< no two landmarks of a zone closer than this [m]
  double corner_quality = 0.05;    ///< Shi-Tomasi threshold, relative to the map's best corner
  int corner_block_px = 5;         ///< neighbourhood of the corner measure [cells]
  double wall_smoothing_m = 0.1;   ///< Gaussian blur of the wall mask before the corner measure [m]
  int candidates_per_landmark = 6; ///< strongest corners considered per landmark wanted
  CellClassParams cells;

  /// "shi-tomasi corners of the wall mask near the zone, farthest-point spread".
  static const char* method() { return "shi-tomasi-farthest-point"; }
};

/// Picks K well-spread structural points per zone: wall corners (room corners, door jambs,
/// junctions, rack ends) near the zone's free space, strongest first and then spread by
/// farthest-point selection. A zone with fewer corners than K is topped up with wall cells
/// farthest from those already chosen. Throws InputError if a zone has no wall near it.
std::vector<ZoneLandmarks> extractLandmarks(const mrpt::maps::COccupancyGridMap2D& grid,
                                            const std::vector<Zone>& zones, const LandmarkParams& params = {});

}  // namespace krp
