// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/local_grid.h"

#include <cmath>
#include <utility>

namespace krp {
namespace {

/// cos and sin of the image heading, with the float residue of quarter turns snapped to zero so
/// that axis-aligned headings map robot points to exactly the same pixels as plain swaps would.
std::pair<double, double> cosSin(double heading_rad) {
  constexpr double kSnap = 1e-12;
  double c = std::cos(heading_rad), s = std::sin(heading_rad);
  if (std::abs(c) < kSnap) c = 0;
  if (std::abs(s) < kSnap) s = 0;
  return {c, s};
}

}  // namespace

// The robot frame is turned by the image heading into an image-aligned frame (x right, y up);
// image rows grow downwards. Heading up (90 deg): robot +x maps to -row, robot +y (left) to
// -column. Pixel centres sit at integer coordinates and the robot at the centre of the image
// (size/2 - 0.5 for even sizes), so the grid is symmetric about the robot.
cv::Point2d LocalGrid::robotToPixel(const mrpt::math::TPoint2D& p) const {
  const double c = 0.5 * (sizePx() - 1);
  const auto [cs, sn] = cosSin(image_heading_rad);
  const double right = cs * p.x - sn * p.y, up = sn * p.x + cs * p.y;
  return {c + right / resolution_m, c - up / resolution_m};
}

mrpt::math::TPoint2D LocalGrid::pixelToRobot(const cv::Point2d& px) const {
  const double c = 0.5 * (sizePx() - 1);
  const auto [cs, sn] = cosSin(image_heading_rad);
  const double right = (px.x - c) * resolution_m, up = (c - px.y) * resolution_m;
  return {cs * right + sn * up, -sn * right + cs * up};
}

}  // namespace krp
