// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/sim/floor_plan.h"

#include <algorithm>
#include <cmath>

namespace krp {
namespace {
constexpr uint8_t kOccupied = 0, kFree = 1, kUnknown = 2;
}

FloorPlan::FloorPlan(double width_m, double height_m, double resolution_m)
    : width_m_(width_m), height_m_(height_m), resolution_m_(resolution_m) {
  occupancy_ = cv::Mat(static_cast<int>(std::lround(height_m / resolution_m)),
                       static_cast<int>(std::lround(width_m / resolution_m)), CV_8U, cv::Scalar(kUnknown));
}

cv::Rect FloorPlan::toPixels(double x0, double y0, double x1, double y1) const {
  const int c0 = static_cast<int>(std::lround(std::min(x0, x1) / resolution_m_));
  const int c1 = static_cast<int>(std::lround(std::max(x0, x1) / resolution_m_));
  const int r0 = occupancy_.rows - static_cast<int>(std::lround(std::max(y0, y1) / resolution_m_));
  const int r1 = occupancy_.rows - static_cast<int>(std::lround(std::min(y0, y1) / resolution_m_));
  return cv::Rect(cv::Point(c0, r0), cv::Point(std::max(c1, c0 + 1), std::max(r1, r0 + 1))) &
         cv::Rect(0, 0, occupancy_.cols, occupancy_.rows);
}

void FloorPlan::paint(double x0, double y0, double x1, double y1, uint8_t value) {
  occupancy_(toPixels(x0, y0, x1, y1)).setTo(value);
}

void FloorPlan::free(double x0, double y0, double x1, double y1) { paint(x0, y0, x1, y1, kFree); }
void FloorPlan::solid(double x0, double y0, double x1, double y1) { paint(x0, y0, x1, y1, kOccupied); }

void FloorPlan::wall(double x0, double y0, double x1, double y1) {
  const double h = wall_thickness_m_ / 2;
  paint(std::min(x0, x1) - h, std::min(y0, y1) - h, std::max(x0, x1) + h, std::max(y0, y1) + h, kOccupied);
}

void FloorPlan::building(double x0, double y0, double x1, double y1) {
  free(x0, y0, x1, y1);
  wall(x0, y0, x1, y0);
  wall(x0, y1, x1, y1);
  wall(x0, y0, x0, y1);
  wall(x1, y0, x1, y1);
}

mrpt::maps::COccupancyGridMap2D FloorPlan::toGrid() const {
  mrpt::maps::COccupancyGridMap2D g(0.0, width_m_, 0.0, height_m_, static_cast<float>(resolution_m_));
  const int h = occupancy_.rows;
  const int rows = std::min(h, static_cast<int>(g.getSizeY())), cols = std::min(occupancy_.cols, static_cast<int>(g.getSizeX()));
  for (int r = h - rows; r < h; ++r)
    for (int c = 0; c < cols; ++c) {
      const uint8_t v = occupancy_.at<uint8_t>(r, c);
      g.setCell(c, h - 1 - r, v == kFree ? 1.0f : (v == kOccupied ? 0.0f : 0.5f));
    }
  return g;
}

}  // namespace krp
