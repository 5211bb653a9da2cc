// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/zones/landmarks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {
namespace {

// Greedy farthest-point selection: starts from the first (strongest) candidate, then adds
// the candidate farthest from all chosen ones; ties keep the stronger (earlier) one.
std::vector<cv::Point2f> farthestPoints(const std::vector<cv::Point2f>& candidates, size_t k,
                                        std::vector<cv::Point2f> chosen = {}) {
  std::vector<double> nearest(candidates.size(), std::numeric_limits<double>::infinity());
  auto update = [&](const cv::Point2f& c) {
    for (size_t i = 0; i < candidates.size(); ++i) nearest[i] = std::min(nearest[i], cv::norm(candidates[i] - c));
  };
  for (const auto& c : chosen) update(c);
  while (chosen.size() < k && !candidates.empty()) {
    size_t best = 0;
    if (!chosen.empty()) best = static_cast<size_t>(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
    if (!chosen.empty() && nearest[best] <= 0.0) break;  // nothing new left
    chosen.push_back(candidates[best]);
    update(candidates[best]);
  }
  return chosen;
}

// Local maxima of `measure` inside `mask` above `floor`, strongest first, no two closer than
// `min_spacing_px`, at most `max_count`.
std::vector<cv::Point2f> strongestCorners(const cv::Mat& measure, const cv::Mat& mask, double floor,
                                          double min_spacing_px, size_t max_count) {
  // Peaks among the mask's cells only: the measure often peaks just off the wall.
  cv::Mat masked = cv::Mat::zeros(measure.size(), CV_32F), local_max;
  measure.copyTo(masked, mask);
  cv::dilate(masked, local_max, cv::Mat::ones(3, 3, CV_8U));
  std::vector<std::pair<float, cv::Point>> peaks;
  for (int r = 0; r < measure.rows; ++r)
    for (int c = 0; c < measure.cols; ++c) {
      const float v = masked.at<float>(r, c);
      if (mask.at<uint8_t>(r, c) && v > floor && v >= local_max.at<float>(r, c)) peaks.push_back({v, {c, r}});
    }
  std::stable_sort(peaks.begin(), peaks.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<cv::Point2f> out;
  for (const auto& [v, pt] : peaks) {
    const cv::Point2f q(static_cast<float>(pt.x), static_cast<float>(pt.y));
    bool spaced = true;
    for (const auto& o : out) spaced = spaced && cv::norm(o - q) >= min_spacing_px;
    if (spaced) out.push_back(q);
    if (out.size() >= max_count) break;
  }
  return out;
}

}  // namespace

std::vector<ZoneLandmarks> extractLandmarks(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                                            const LandmarkParams& p) {
  if (p.keypoints_per_zone < 3) throw InputError("landmark parameters", "keypoints_per_zone must be at least 3");
  const double res = grid.getResolution();
  const cv::Mat occupied = occupiedMask(grid, p.cells);
  const cv::Mat free = freeMask(grid, p.cells);
  const cv::Mat labels = rasterizeZones(grid, zones);

  // Wall cells that touch free space: what a lidar can actually see.
  cv::Mat free_near;
  cv::dilate(free, free_near, cv::Mat::ones(3, 3, CV_8U));
  const cv::Mat visible_wall = occupied & free_near;

  cv::Mat smooth;
  const int blur_px = 2 * std::max(1, static_cast<int>(std::lround(p.wall_smoothing_m / res))) + 1;
  cv::GaussianBlur(occupied, smooth, cv::Size(blur_px, blur_px), 0);

  // Shi-Tomasi measure (smaller eigenvalue of the structure tensor): high at corners and
  // wall ends, near zero along straight walls. The threshold is relative to the map's best
  // corner so that every zone is held to the same standard.
  cv::Mat corner_measure;
  cv::cornerMinEigenVal(smooth, corner_measure, p.corner_block_px, 3);
  double best_corner = 0;
  cv::minMaxLoc(corner_measure, nullptr, &best_corner, nullptr, nullptr, visible_wall);
  const double quality_floor = p.corner_quality * best_corner;

  const int margin_px = std::max(1, static_cast<int>(std::lround(p.search_margin_m / res)));
  const cv::Mat margin_kernel =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * margin_px + 1, 2 * margin_px + 1));
  const size_t k = static_cast<size_t>(p.keypoints_per_zone);

  std::vector<ZoneLandmarks> out;
  for (size_t z = 0; z < zones.size(); ++z) {
    cv::Mat region = (labels == static_cast<int>(z)) & free;
    cv::dilate(region, region, margin_kernel);
    const cv::Mat search = region & visible_wall;
    if (cv::countNonZero(search) == 0)
      throw InputError("zone '" + zones[z].name + "'", "has no wall within " + std::to_string(p.search_margin_m) +
                                                           " m of its free space to take landmarks from");
    const auto corners = strongestCorners(corner_measure, search, quality_floor, p.min_spacing_m / res,
                                          k * static_cast<size_t>(p.candidates_per_landmark));
    auto chosen = farthestPoints(corners, k);
    if (chosen.size() < k) {
      std::vector<cv::Point> wall_cells;
      cv::findNonZero(search, wall_cells);
      std::vector<cv::Point2f> fallback;
      for (const auto& w : wall_cells) fallback.emplace_back(static_cast<float>(w.x), static_cast<float>(w.y));
      chosen = farthestPoints(fallback, k, chosen);
    }
    if (chosen.size() < k)
      throw InputError("zone '" + zones[z].name + "'", "has only " + std::to_string(chosen.size()) +
                                                           " distinct wall cells for " + std::to_string(k) + " landmarks");
    ZoneLandmarks zl;
    zl.zone = zones[z].name;
    for (const auto& c : chosen) zl.points.push_back(pixelToWorld(grid, cv::Point2d(c.x, c.y)));
    out.push_back(std::move(zl));
  }
  return out;
}

}  // namespace krp
