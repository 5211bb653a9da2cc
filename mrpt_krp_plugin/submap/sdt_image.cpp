// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/sdt_image.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/submap/seismic_colormap.h"

namespace krp {

cv::Mat signedDistanceM(const LocalGrid& grid) {
  const cv::Mat free = grid.cells == static_cast<int>(CellState::kFree);
  const cv::Mat occupied = grid.cells == static_cast<int>(CellState::kOccupied);
  // distanceTransform measures to the nearest zero pixel.
  cv::Mat to_obstacle, to_free;
  cv::distanceTransform(~occupied, to_obstacle, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::distanceTransform(~free, to_free, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const float diagonal = static_cast<float>(std::hypot(grid.cells.cols, grid.cells.rows));
  cv::min(to_obstacle, diagonal, to_obstacle);
  cv::min(to_free, diagonal, to_free);
  cv::Mat sdt(grid.cells.size(), CV_32F);
  to_obstacle.copyTo(sdt, free);
  cv::Mat negative = -to_free;
  negative.copyTo(sdt, ~free);
  return sdt * grid.resolution_m;
}

cv::Mat renderSdtImage(const LocalGrid& grid, const SdtImageParams& params) {
  if (!(params.clip_m > 0) || !std::isfinite(params.clip_m)) throw InputError("SDT image", "clip_m must be > 0");
  const cv::Mat sdt = signedDistanceM(grid);
  // [-clip, clip] -> [0, 255]; convertTo saturates outside.
  cv::Mat index;
  sdt.convertTo(index, CV_8U, 127.5 / params.clip_m, 127.5);
  cv::Mat index3, out;
  cv::cvtColor(index, index3, cv::COLOR_GRAY2BGR);
  cv::LUT(index3, seismicLutBgr(), out);
  return out;
}

}  // namespace krp
