// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/occupancy_image.h"

namespace krp {

cv::Mat renderOccupancyImage(const LocalGrid& grid, const OccupancyImageLevels& levels) {
  cv::Mat img(grid.cells.size(), CV_8U, cv::Scalar(levels.unknown));
  img.setTo(levels.free, grid.cells == static_cast<int>(CellState::kFree));
  img.setTo(levels.occupied, grid.cells == static_cast<int>(CellState::kOccupied));
  return img;
}

}  // namespace krp
