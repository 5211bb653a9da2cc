// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>

#include <string>
#include <vector>

#include "mrpt_krp_plugin/dataset/keypoint_label.h"

namespace krp {

/// A contact sheet of dataset samples, for a person to check what the models will see: per
/// sample the occupancy image beside the SDT image with its keypoints (green = observed,
/// yellow = inside but not observed, numbered in landmark order), one zone per row.
class DatasetPreview {
 public:
  explicit DatasetPreview(int samples_per_row, int scale = 2) : per_row_(samples_per_row), scale_(scale) {}
  /// Adds a sample to the row of `zone` (ignored once that row is full).
  void add(size_t zone, const cv::Mat& occupancy, const cv::Mat& sdt, const std::vector<Keypoint>& keypoints);
  /// Writes the sheet as PNG (nothing if no sample was added).
  void write(const std::string& png_path) const;

 private:
  int per_row_;
  int scale_;
  std::vector<std::vector<cv::Mat>> rows_;
};

}  // namespace krp
