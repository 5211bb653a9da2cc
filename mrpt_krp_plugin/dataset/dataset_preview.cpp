// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/dataset/dataset_preview.h"

#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/png_file.h"

namespace krp {
namespace {
const cv::Scalar kObservedBgr(0, 200, 0), kNotObservedBgr(0, 220, 255), kGapBgr(90, 90, 90);
constexpr int kGapPx = 4;
}  // namespace

void DatasetPreview::add(size_t zone, const cv::Mat& occupancy, const cv::Mat& sdt, const std::vector<Keypoint>& kps) {
  if (rows_.size() <= zone) rows_.resize(zone + 1);
  if (static_cast<int>(rows_[zone].size()) >= per_row_) return;
  cv::Mat occ3, occ_big, sdt_big;
  cv::cvtColor(occupancy, occ3, cv::COLOR_GRAY2BGR);
  cv::resize(occ3, occ_big, cv::Size(), scale_, scale_, cv::INTER_NEAREST);
  cv::resize(sdt, sdt_big, cv::Size(), scale_, scale_, cv::INTER_NEAREST);
  for (size_t i = 0; i < kps.size(); ++i) {
    if (kps[i].visibility == KeypointVisibility::kOutside) continue;
    const cv::Point c(static_cast<int>((kps[i].px.x + kPixelCentreOffset) * scale_),
                      static_cast<int>((kps[i].px.y + kPixelCentreOffset) * scale_));
    const auto colour = kps[i].visibility == KeypointVisibility::kObserved ? kObservedBgr : kNotObservedBgr;
    cv::circle(sdt_big, c, 3 * scale_, colour, 2);
    cv::putText(sdt_big, std::to_string(i), c + cv::Point(4 * scale_, 0), cv::FONT_HERSHEY_SIMPLEX, 0.3 * scale_, colour, 1);
  }
  cv::Mat tile;
  cv::hconcat(std::vector<cv::Mat>{occ_big, cv::Mat(occ_big.rows, kGapPx, CV_8UC3, kGapBgr), sdt_big}, tile);
  rows_[zone].push_back(tile);
}

void DatasetPreview::write(const std::string& png_path) const {
  std::vector<cv::Mat> lines;
  cv::Size tile_size;
  for (const auto& r : rows_)
    if (!r.empty()) tile_size = r.front().size();
  if (tile_size.area() == 0) return;
  for (const auto& r : rows_) {
    std::vector<cv::Mat> parts;
    for (int i = 0; i < per_row_; ++i) {
      parts.push_back(i < static_cast<int>(r.size()) ? r[i] : cv::Mat(tile_size, CV_8UC3, kGapBgr));
      parts.push_back(cv::Mat(tile_size.height, 2 * kGapPx, CV_8UC3, kGapBgr));
    }
    cv::Mat line;
    cv::hconcat(parts, line);
    lines.push_back(line);
    lines.push_back(cv::Mat(2 * kGapPx, line.cols, CV_8UC3, kGapBgr));
  }
  cv::Mat sheet;
  cv::vconcat(lines, sheet);
  writePngAtomically(png_path, sheet);
}

}  // namespace krp
