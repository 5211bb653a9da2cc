// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/zones/zone.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {

cv::Mat rasterizeZones(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones) {
  cv::Mat labels(static_cast<int>(grid.getSizeY()), static_cast<int>(grid.getSizeX()), CV_32S, cv::Scalar(-1));
  for (size_t i = 0; i < zones.size(); ++i) {
    std::vector<cv::Point> px;
    for (const auto& p : zones[i].polygon) px.push_back(worldToPixel(grid, p));
    if (px.size() >= 3) cv::fillPoly(labels, std::vector<std::vector<cv::Point>>{px}, cv::Scalar(static_cast<int>(i)));
  }
  return labels;
}

ZoneIndex::ZoneIndex(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones)
    : grid_(grid), labels_(rasterizeZones(grid, zones)) {}

int ZoneIndex::zoneAt(const mrpt::math::TPoint2D& p) const {
  const cv::Point px = worldToPixel(grid_, p);
  if (px.x < 0 || px.y < 0 || px.x >= labels_.cols || px.y >= labels_.rows) return -1;
  return labels_.at<int>(px);
}

double polygonAreaM2(const std::vector<mrpt::math::TPoint2D>& poly) {
  double a = 0.0;
  for (size_t i = 0, n = poly.size(); i < n; ++i) {
    const auto& p = poly[i];
    const auto& q = poly[(i + 1) % n];
    a += p.x * q.y - q.x * p.y;
  }
  return std::abs(a) / 2.0;
}

}  // namespace krp
