// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <opencv2/core.hpp>

namespace krp {

/// A drawing board for building maps in metres: everything starts unknown (outside the
/// building), then rooms are carved free and walls drawn occupied.
class FloorPlan {
 public:
  FloorPlan(double width_m, double height_m, double resolution_m);

  void free(double x0, double y0, double x1, double y1);
  void solid(double x0, double y0, double x1, double y1);
  /// A wall of the plan's wall thickness from (x0, y0) to (x1, y1), axis-aligned.
  void wall(double x0, double y0, double x1, double y1);
  /// Outer walls around the rectangle, which is also made free inside.
  void building(double x0, double y0, double x1, double y1);

  double wallThicknessM() const { return wall_thickness_m_; }
  mrpt::maps::COccupancyGridMap2D toGrid() const;

 private:
  cv::Rect toPixels(double x0, double y0, double x1, double y1) const;
  void paint(double x0, double y0, double x1, double y1, uint8_t value);

  double width_m_, height_m_, resolution_m_;
  double wall_thickness_m_ = 0.15;  ///< interior and exterior walls [m]
  cv::Mat occupancy_;               ///< 0 occupied, 1 free, 2 unknown; row 0 at y = height
};

}  // namespace krp
