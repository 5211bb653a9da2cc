// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/sim/clutter.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {
namespace {
constexpr double kPalletLengthM = 1.2, kPalletWidthM = 0.8;  // EUR pallet
constexpr double kLegRadiusM = 0.07, kLegSpacingM = 0.25;    // a person seen at shin height

void fillRotatedBox(mrpt::maps::COccupancyGridMap2D& g, double cx, double cy, double lx, double ly, double yaw) {
  const double c = std::cos(yaw), s = std::sin(yaw), r = g.getResolution();
  for (double u = -lx / 2; u <= lx / 2; u += r / 2)
    for (double v = -ly / 2; v <= ly / 2; v += r / 2) {
      const int ix = g.x2idx(cx + c * u - s * v), iy = g.y2idx(cy + s * u + c * v);
      if (ix >= 0 && iy >= 0 && ix < static_cast<int>(g.getSizeX()) && iy < static_cast<int>(g.getSizeY()))
        g.setCell(ix, iy, 0.0f);
    }
}

void fillDisc(mrpt::maps::COccupancyGridMap2D& g, double cx, double cy, double radius) {
  const double r = g.getResolution();
  for (double u = -radius; u <= radius; u += r / 2)
    for (double v = -radius; v <= radius; v += r / 2)
      if (u * u + v * v <= radius * radius) {
        const int ix = g.x2idx(cx + u), iy = g.y2idx(cy + v);
        if (ix >= 0 && iy >= 0 && ix < static_cast<int>(g.getSizeX()) && iy < static_cast<int>(g.getSizeY()))
          g.setCell(ix, iy, 0.0f);
      }
}
}  // namespace

mrpt::maps::COccupancyGridMap2D addClutter(const mrpt::maps::COccupancyGridMap2D& map, const ClutterParams& p,
                                           Rng& rng) {
  mrpt::maps::COccupancyGridMap2D out = map;
  const cv::Mat dist = freeClearanceM(map);
  std::vector<cv::Point> candidates;
  cv::findNonZero(dist > p.placement_clearance_m, candidates);
  if (candidates.empty()) return out;
  const double free_m2 = freeAreaM2(map);
  auto count = [&](double per100) { return static_cast<int>(std::lround(per100 * free_m2 / 100.0)); };
  auto pick = [&]() {
    const auto& px = candidates[static_cast<size_t>(rng.uniformInt(0, static_cast<int>(candidates.size()) - 1))];
    return pixelToWorld(map, px);
  };
  for (int i = 0, n = count(p.boxes_per_100m2); i < n; ++i) {
    const auto c = pick();
    fillRotatedBox(out, c.x, c.y, rng.uniform(p.box_min_side_m, p.box_max_side_m),
                   rng.uniform(p.box_min_side_m, p.box_max_side_m), rng.uniform(-M_PI, M_PI));
  }
  for (int i = 0, n = count(p.pallets_per_100m2); i < n; ++i) {
    const auto c = pick();
    fillRotatedBox(out, c.x, c.y, kPalletLengthM, kPalletWidthM, rng.uniform(-M_PI, M_PI));
  }
  for (int i = 0, n = count(p.people_per_100m2); i < n; ++i) {
    const auto c = pick();
    const double yaw = rng.uniform(-M_PI, M_PI);
    for (int leg : {-1, 1})
      fillDisc(out, c.x + leg * kLegSpacingM / 2 * std::cos(yaw), c.y + leg * kLegSpacingM / 2 * std::sin(yaw),
               kLegRadiusM);
  }
  return out;
}

}  // namespace krp
