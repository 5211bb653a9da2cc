// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/dataset/scenario.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {
namespace {

constexpr double kChangedFactor = 3.0;          // harsher clutter and occlusion in the changed split
constexpr double kChangedFurnitureShare = 1.0 / 3.0;

// Moves a share of the small occupied blobs (furniture) by a random shift, in the grid's cells.
void moveFurniture(mrpt::maps::COccupancyGridMap2D& g, const ScenarioParams& p, Rng& rng) {
  const cv::Mat occupied = occupiedMask(g);
  cv::Mat comp, stats, centroids;
  const int n = cv::connectedComponentsWithStats(occupied, comp, stats, centroids, 8, CV_32S);
  const double cell_area = g.getResolution() * g.getResolution();
  const int shift_cells = static_cast<int>(std::lround(p.furniture_max_shift_m / g.getResolution()));
  for (int k = 1; k < n; ++k) {
    if (stats.at<int>(k, cv::CC_STAT_AREA) * cell_area > p.furniture_max_area_m2) continue;
    if (!rng.bernoulli(p.moved_furniture_fraction)) continue;
    const int dx = rng.uniformInt(-shift_cells, shift_cells), dy = rng.uniformInt(-shift_cells, shift_cells);
    std::vector<cv::Point> cells;
    cv::findNonZero(comp == k, cells);
    // Only onto free floor: a piece that would hit a wall stays where it is.
    bool fits = true;
    for (const auto& c : cells) {
      const int x = c.x + dx, y = c.y + dy;
      if (x < 0 || y < 0 || x >= occupied.cols || y >= occupied.rows) { fits = false; break; }
      const int label = comp.at<int>(y, x);
      if (label != 0 && label != k) { fits = false; break; }
    }
    if (!fits) continue;
    constexpr float kFree = 1.0f, kOccupied = 0.0f;  // MRPT cell values are p(free)
    for (const auto& c : cells) {
      const auto w = pixelToWorld(g, c);
      g.setPos(w.x, w.y, kFree);
    }
    for (const auto& c : cells) {
      const auto w = pixelToWorld(g, c + cv::Point(dx, dy));
      g.setPos(w.x, w.y, kOccupied);
    }
  }
}

}  // namespace

ScenarioParams ScenarioParams::changedEnvironment() const {
  ScenarioParams c = *this;
  c.clutter_scale *= kChangedFactor;
  c.occlusion_probability = std::min(1.0, occlusion_probability * kChangedFactor);
  c.moved_furniture_fraction = kChangedFurnitureShare;
  if (c.strength <= 0) c.strength = 1.0;  // the changed split is always changed
  return c;
}

mrpt::maps::COccupancyGridMap2D scenarioWorld(const mrpt::maps::COccupancyGridMap2D& map, const ClutterParams& clutter,
                                              const ScenarioParams& p, Rng& rng) {
  if (p.strength <= 0) return map;
  ClutterParams c = clutter;
  const double k = p.strength * p.clutter_scale;
  c.boxes_per_100m2 *= k;
  c.pallets_per_100m2 *= k;
  c.people_per_100m2 *= k;
  auto world = addClutter(map, c, rng);
  if (p.moved_furniture_fraction > 0) moveFurniture(world, p, rng);
  return world;
}

LidarProfile scenarioLidar(const LidarProfile& lidar, const ScenarioParams& p) {
  LidarProfile l = lidar;
  if (p.strength <= 0) return l;
  l.range_noise_std_m = std::hypot(l.range_noise_std_m, p.strength * p.extra_range_noise_m);
  l.dropout_probability = std::min(0.9, l.dropout_probability + p.strength * p.extra_dropout);
  return l;
}

bool applyOcclusion(mrpt::obs::CObservation2DRangeScan& scan, const ScenarioParams& p, Rng& rng) {
  if (p.strength <= 0 || !rng.bernoulli(std::min(1.0, p.strength * p.occlusion_probability))) return false;
  const size_t n = scan.getScanSize();
  if (n < 2) return false;
  const double step = scan.aperture / static_cast<double>(n - 1);
  const double width = rng.uniform(0.2, 1.0) * p.occlusion_max_sector_deg * M_PI / 180.0;
  const size_t count = std::min(n, static_cast<size_t>(width / step));
  const size_t first = static_cast<size_t>(rng.uniformInt(0, static_cast<int>(n - 1)));
  const double range = rng.uniform(p.occlusion_min_range_m, p.occlusion_max_range_m);
  for (size_t k = 0; k < count; ++k) {
    const size_t i = (first + k) % n;
    if (scan.getScanRangeValidity(i) && scan.getScanRange(i) < range) continue;  // already closer
    scan.setScanRange(i, static_cast<float>(range));
    scan.setScanRangeValidity(i, true);
  }
  return true;
}

}  // namespace krp
