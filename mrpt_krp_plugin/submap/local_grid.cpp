// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/local_grid.h"

namespace krp {

// Heading up: robot +x maps to -row, robot +y (left) maps to -column. Pixel centres sit at
// integer coordinates and the robot at the centre of the image (size/2 - 0.5 for even sizes),
// so the grid is symmetric about the robot.
cv::Point2d LocalGrid::robotToPixel(const mrpt::math::TPoint2D& p) const {
  const double c = 0.5 * (sizePx() - 1);
  return {c - p.y / resolution_m, c - p.x / resolution_m};
}

mrpt::math::TPoint2D LocalGrid::pixelToRobot(const cv::Point2d& px) const {
  const double c = 0.5 * (sizePx() - 1);
  return {(c - px.y) * resolution_m, (c - px.x) * resolution_m};
}

}  // namespace krp
