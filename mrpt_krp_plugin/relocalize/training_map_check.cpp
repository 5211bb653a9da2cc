// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/training_map_check.h"

#include <cmath>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {

namespace {

/// Whether an occupied pixel of `mask` lies within `radius_px` of `centre`.
bool occupiedWithin(const cv::Mat& mask, const cv::Point& centre, int radius_px) {
  for (int dy = -radius_px; dy <= radius_px; ++dy)
    for (int dx = -radius_px; dx <= radius_px; ++dx) {
      if (dx * dx + dy * dy > radius_px * radius_px) continue;
      const cv::Point p(centre.x + dx, centre.y + dy);
      if (p.x >= 0 && p.y >= 0 && p.x < mask.cols && p.y < mask.rows && mask.at<uint8_t>(p) != 0) return true;
    }
  return false;
}

bool insideMap(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::math::TPoint2D& p) {
  return p.x >= map.getXMin() && p.x <= map.getXMax() && p.y >= map.getYMin() && p.y <= map.getYMax();
}

}  // namespace

double landmarkShareOnWalls(const ModelManifest& manifest, const mrpt::maps::COccupancyGridMap2D& map,
                            const TrainingMapCheckParams& params) {
  const cv::Mat occupied = occupiedMask(map);
  const int radius_px = static_cast<int>(std::floor(params.landmark_wall_distance_m / map.getResolution()));
  int all = 0, on_walls = 0;
  for (const auto& zone : manifest.landmarks)
    for (const auto& landmark : zone) {
      ++all;
      if (insideMap(map, landmark) && occupiedWithin(occupied, worldToPixel(map, landmark), radius_px)) ++on_walls;
    }
  return all == 0 ? 1.0 : static_cast<double>(on_walls) / all;
}

void requireTrainingMap(const ModelManifest& manifest, const mrpt::maps::COccupancyGridMap2D& map,
                        const TrainingMapCheckParams& params) {
  const std::string input = manifest.folder + "/manifest.json";
  if (manifest.map_resolution_m > 0 &&
      std::abs(map.getResolution() - manifest.map_resolution_m) > params.resolution_tolerance_m) {
    std::ostringstream s;
    s << "the models were trained on a map of " << manifest.map_resolution_m << " m cells (world '" << manifest.world
      << "'); this map has " << map.getResolution() << " m cells";
    throw InputError(input, s.str());
  }
  for (size_t z = 0; z < manifest.landmarks.size(); ++z)
    for (const auto& p : manifest.landmarks[z])
      if (!insideMap(map, p))
        throw InputError(input, "landmark of zone '" + manifest.zones[z] +
                                    "' lies outside the map: the models were trained on another map (world '" +
                                    manifest.world + "')");
  const double share = landmarkShareOnWalls(manifest, map, params);
  if (share < params.min_landmark_share_on_walls) {
    std::ostringstream s;
    s << "only " << std::lround(100 * share) << " % of the models' landmarks lie on this map's walls (within "
      << params.landmark_wall_distance_m << " m; at least " << std::lround(100 * params.min_landmark_share_on_walls)
      << " % must): the models were trained on another map (world '" << manifest.world
      << "'); train models for this map with krp-train-map";
    throw InputError(input, s.str());
  }
}

}  // namespace krp
