// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/grid_image.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace krp {

cv::Point worldToPixel(const mrpt::maps::COccupancyGridMap2D& grid, const mrpt::math::TPoint2D& p) {
  const int cx = static_cast<int>(std::floor((p.x - grid.getXMin()) / grid.getResolution()));
  const int cy = static_cast<int>(std::floor((p.y - grid.getYMin()) / grid.getResolution()));
  return {cx, static_cast<int>(grid.getSizeY()) - 1 - cy};
}

mrpt::math::TPoint2D pixelToWorld(const mrpt::maps::COccupancyGridMap2D& grid, const cv::Point2d& px) {
  const double r = grid.getResolution();
  const double cy = static_cast<double>(grid.getSizeY()) - 1.0 - px.y;
  return {grid.getXMin() + (px.x + 0.5) * r, grid.getYMin() + (cy + 0.5) * r};
}

namespace {
template <typename CellToByte>
cv::Mat renderGrid(const mrpt::maps::COccupancyGridMap2D& grid, CellToByte f) {
  const int w = static_cast<int>(grid.getSizeX()), h = static_cast<int>(grid.getSizeY());
  cv::Mat img(h, w, CV_8UC1);
  for (int cy = 0; cy < h; ++cy) {
    auto* row = img.ptr<uint8_t>(h - 1 - cy);
    for (int cx = 0; cx < w; ++cx) row[cx] = f(1.0 - grid.getCell(cx, cy));
  }
  return img;
}
}  // namespace

cv::Mat gridToGrey(const mrpt::maps::COccupancyGridMap2D& grid) {
  return renderGrid(grid, [](double occ) { return static_cast<uint8_t>(std::lround(255.0 * (1.0 - occ))); });
}

cv::Mat freeMask(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p) {
  return renderGrid(grid, [&](double occ) { return static_cast<uint8_t>(occ < p.max_free_occupancy ? 255 : 0); });
}

cv::Mat freeClearanceM(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p) {
  cv::Mat dist;
  cv::distanceTransform(freeMask(grid, p), dist, cv::DIST_L2, cv::DIST_MASK_5);
  return dist * grid.getResolution();
}

cv::Mat occupiedMask(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p) {
  return renderGrid(grid, [&](double occ) { return static_cast<uint8_t>(occ > p.min_occupied_occupancy ? 255 : 0); });
}

cv::Mat obstacleDistanceByCell(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p) {
  cv::Mat by_cell_row;
  cv::flip(occupiedMask(grid, p) == 0, by_cell_row, 0);
  cv::Mat dist;
  cv::distanceTransform(by_cell_row, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return dist;
}

std::vector<cv::Point> maskedCells(const cv::Mat& mask) {
  cv::Mat cell_rows;
  cv::flip(mask, cell_rows, 0);  // image row 0 is the top; cell row 0 is the bottom
  std::vector<cv::Point> cells;
  cv::findNonZero(cell_rows, cells);
  return cells;
}

}  // namespace krp
