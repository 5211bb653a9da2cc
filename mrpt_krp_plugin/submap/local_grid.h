// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <opencv2/core.hpp>

#include <cmath>

namespace krp {

/// Pixel coordinates here put pixel centres at integers; continuous image coordinates (what
/// YOLO labels and drawing use) put the image's edges at 0 and size. The one offset between them:
/// continuous = pixel-centre + kPixelCentreOffset, and a pixel covers [c - offset, c + offset).
constexpr double kPixelCentreOffset = 0.5;

/// What a submap cell is known to be.
enum class CellState : uint8_t { kUnknown = 0, kFree = 1, kOccupied = 2 };

/// The robot's heading in a heading-up submap: its forward axis points to row 0.
constexpr double kHeadingUpRad = M_PI / 2;

/// A robot-centric local occupancy grid: the robot at the centre, drawn at `image_heading_rad`.
/// One cell is one image pixel of the images the models see.
struct LocalGrid {
  cv::Mat cells;             ///< CV_8U of CellState, size_px x size_px
  double resolution_m = 0;   ///< cell side [m]
  /// The robot's heading in the image: 0 along increasing columns, counter-clockwise positive
  /// (towards row 0) [rad]. kHeadingUpRad draws the robot's forward axis up; wall-aligned submaps
  /// use a heading that puts the walls along rows and columns (submap/wall_axes.h).
  double image_heading_rad = kHeadingUpRad;

  int sizePx() const { return cells.rows; }
  /// Pixel (column, row) of a point given in the robot frame (x forward, y left) [m].
  /// The one place where the robot frame meets submap image coordinates.
  cv::Point2d robotToPixel(const mrpt::math::TPoint2D& p) const;
  /// The robot-frame point at the centre of pixel (column, row).
  mrpt::math::TPoint2D pixelToRobot(const cv::Point2d& px) const;
  CellState at(int col, int row) const { return static_cast<CellState>(cells.at<uint8_t>(row, col)); }
};

}  // namespace krp
