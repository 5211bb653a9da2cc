// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/wall_axes.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/grid_image.h"
#include "mrpt_krp_plugin/submap/scan_beams.h"

namespace krp {
namespace {

constexpr double kQuarterTurn = M_PI / 2;

void validate(const WallAxesParams& p) {
  if (!(p.bin_deg > 0 && p.bin_deg <= 15) || !(p.map_blur_cells > 0 && p.map_blur_cells <= 10) || !(p.smoothing_deg >= 0 && p.smoothing_deg < 90) ||
      !(p.min_neighbour_gap_m >= 0 && p.max_neighbour_gap_m > p.min_neighbour_gap_m) ||
      !(p.min_support >= 0 && p.min_support <= 1))
    throw InputError("wall axes parameters",
                     "need 0 < bin_deg <= 15, 0 < map_blur_cells <= 10, 0 <= smoothing_deg < 90, 0 <= min gap < max gap, min_support in [0, 1]");
}

/// A histogram of directions modulo 90 deg, weighted.
class QuarterTurnHistogram {
 public:
  explicit QuarterTurnHistogram(const WallAxesParams& p)
      : bins_(std::max(1, static_cast<int>(std::lround(90.0 / p.bin_deg))), 0.0), params_(p) {}

  void add(double direction_rad, double weight) {
    double a = std::fmod(direction_rad, kQuarterTurn);
    if (a < 0) a += kQuarterTurn;
    const int n = static_cast<int>(bins_.size());
    bins_[std::min(n - 1, static_cast<int>(a / kQuarterTurn * n))] += weight;
    total_ += weight;
  }

  WallAxes peak() const {
    WallAxes out;
    if (!(total_ > 0)) return out;
    const int n = static_cast<int>(bins_.size());
    const int half = static_cast<int>(std::lround(params_.smoothing_deg / params_.bin_deg / 2));
    double best = -1;
    int best_bin = 0;
    for (int i = 0; i < n; ++i) {
      double s = 0;
      for (int d = -half; d <= half; ++d) s += bins_[((i + d) % n + n) % n];
      if (s > best) best = s, best_bin = i;
    }
    // The weighted mean direction inside the window refines the peak below the bin width.
    double sum = 0, offset = 0;
    for (int d = -half; d <= half; ++d) {
      const double w = bins_[((best_bin + d) % n + n) % n];
      sum += w;
      offset += w * d;
    }
    const double bin_rad = kQuarterTurn / n;
    double angle = (best_bin + 0.5 + (sum > 0 ? offset / sum : 0)) * bin_rad;
    if (angle >= kQuarterTurn / 2) angle -= kQuarterTurn;  // into [-45, 45) deg
    out.angle_rad = angle;
    out.support = best / total_;
    out.found = out.support >= params_.min_support;
    return out;
  }

 private:
  std::vector<double> bins_;
  double total_ = 0;
  const WallAxesParams& params_;
};

}  // namespace

WallAxes scanWallAxes(const mrpt::obs::CObservation2DRangeScan& scan, const WallAxesParams& params) {
  validate(params);
  const auto beams = scanBeams(scan);
  const mrpt::poses::CPose2D sensor(scan.sensorPose);
  QuarterTurnHistogram hist(params);
  bool have_previous = false;
  mrpt::math::TPoint2D previous;
  for (const auto& b : beams.beams) {
    if (!b.hit) {
      have_previous = false;
      continue;
    }
    mrpt::math::TPoint2D p;
    sensor.composePoint(b.range_m * std::cos(b.angle_rad), b.range_m * std::sin(b.angle_rad), p.x, p.y);
    if (have_previous) {
      const double dx = p.x - previous.x, dy = p.y - previous.y, gap = std::hypot(dx, dy);
      if (gap >= params.min_neighbour_gap_m && gap <= params.max_neighbour_gap_m) hist.add(std::atan2(dy, dx), gap);
    }
    // A skipped too-close neighbour keeps the older point, so dense scans still give segments.
    if (!have_previous || std::hypot(p.x - previous.x, p.y - previous.y) >= params.min_neighbour_gap_m) previous = p;
    have_previous = true;
  }
  return hist.peak();
}

WallAxes mapWallAxes(const mrpt::maps::COccupancyGridMap2D& map, const WallAxesParams& params) {
  validate(params);
  if (map.getSizeX() < 3 || map.getSizeY() < 3) return {};
  cv::Mat occupied;
  occupiedMask(map).convertTo(occupied, CV_32F, 1.0 / 255.0);
  // Blurring first spreads a pixel staircase's gradients over all directions, so a round or
  // slanted wall does not vote for the grid's own axes.
  cv::GaussianBlur(occupied, occupied, cv::Size(), params.map_blur_cells);
  cv::Mat gx, gy;
  cv::Sobel(occupied, gx, CV_32F, 1, 0);
  cv::Sobel(occupied, gy, CV_32F, 0, 1);
  QuarterTurnHistogram hist(params);
  for (int row = 0; row < occupied.rows; ++row)
    for (int col = 0; col < occupied.cols; ++col) {
      // Image rows grow downwards, map y upwards: the row gradient is minus the map's y gradient.
      const double ax = gx.at<float>(row, col), ay = -gy.at<float>(row, col), m = std::hypot(ax, ay);
      // A wall's edge is perpendicular to the gradient; modulo 90 deg the two are the same axis.
      if (m > 0) hist.add(std::atan2(ay, ax), m);
    }
  return hist.peak();
}

std::vector<double> wallAlignedImageHeadings(const WallAxes& scan_axes) {
  std::vector<double> out;
  for (int k = 0; k < 4; ++k) out.push_back(mrpt::math::wrapToPi(-scan_axes.angle_rad + k * kQuarterTurn));
  return out;
}

std::vector<double> wallAlignedMapHeadings(const WallAxes& scan_axes, const WallAxes& map_axes) {
  std::vector<double> out;
  for (int k = 0; k < 4; ++k) out.push_back(mrpt::math::wrapToPi(map_axes.angle_rad - scan_axes.angle_rad + k * kQuarterTurn));
  return out;
}

double nearestHeading(const std::vector<double>& candidates_rad, double heading_rad) {
  double best = std::numeric_limits<double>::quiet_NaN(), best_diff = std::numeric_limits<double>::infinity();
  for (double c : candidates_rad) {
    const double d = std::abs(mrpt::math::wrapToPi(c - heading_rad));
    if (d < best_diff) best_diff = d, best = c;
  }
  return best;
}

}  // namespace krp
