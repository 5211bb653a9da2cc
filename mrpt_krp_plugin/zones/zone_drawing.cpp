// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/zones/zone_drawing.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/png_file.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {

cv::Scalar zoneColour(size_t i) {
  // Golden-angle hue steps keep neighbouring indices far apart in colour.
  constexpr double kGoldenAngleDeg = 137.508;
  const double hue = std::fmod(static_cast<double>(i) * kGoldenAngleDeg, 360.0) / 2.0;  // OpenCV hue is 0..180
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue, 200, 230)), bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  const auto v = bgr.at<cv::Vec3b>(0, 0);
  return {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])};
}

double zoneDrawingScale(const mrpt::maps::COccupancyGridMap2D& grid, const ZoneDrawingParams& p) {
  const int cols = static_cast<int>(grid.getSizeX());
  if (cols < p.min_image_width_px) return std::ceil(static_cast<double>(p.min_image_width_px) / cols);
  if (cols > p.max_image_width_px) return static_cast<double>(p.max_image_width_px) / cols;
  return 1.0;
}

cv::Point zoneDrawingPixel(const mrpt::maps::COccupancyGridMap2D& grid, const mrpt::math::TPoint2D& p, double scale) {
  const cv::Point q = worldToPixel(grid, p);
  return {static_cast<int>((q.x + 0.5) * scale), static_cast<int>((q.y + 0.5) * scale)};
}

cv::Mat drawZones(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                  const ZoneDrawingParams& p) {
  cv::Mat grey = gridToGrey(grid), img;
  cv::cvtColor(grey, img, cv::COLOR_GRAY2BGR);
  const double scale = zoneDrawingScale(grid, p);
  cv::resize(img, img, cv::Size(), scale, scale, cv::INTER_NEAREST);

  cv::Mat tint = img.clone();
  std::vector<std::vector<cv::Point>> outlines;
  for (size_t i = 0; i < zones.size(); ++i) {
    std::vector<cv::Point> px;
    for (const auto& pt : zones[i].polygon) px.push_back(zoneDrawingPixel(grid, pt, scale));
    cv::fillPoly(tint, std::vector<std::vector<cv::Point>>{px}, zoneColour(i));
    outlines.push_back(px);
  }
  cv::addWeighted(tint, p.fill_opacity, img, 1.0 - p.fill_opacity, 0.0, img);
  const int thickness = std::max(1, static_cast<int>(std::lround(img.cols / 800.0)));
  for (size_t i = 0; i < outlines.size(); ++i) cv::polylines(img, outlines[i], true, zoneColour(i) * 0.6, thickness);

  const double font = std::max(0.35, img.cols / 3600.0);
  for (size_t i = 0; i < zones.size(); ++i) {
    if (outlines[i].size() < 3) continue;
    // The label goes where the zone is widest (farthest from its outline), on two short lines,
    // so that it stays inside narrow or non-convex zones and off its neighbours' labels.
    // A one-pixel empty border: distanceTransform treats the image edge as far away.
    cv::Mat inside = cv::Mat::zeros(img.rows + 2, img.cols + 2, CV_8U), dist;
    cv::fillPoly(inside, std::vector<std::vector<cv::Point>>{outlines[i]}, cv::Scalar(255), cv::LINE_8, 0,
                 cv::Point(1, 1));
    cv::distanceTransform(inside, dist, cv::DIST_L2, cv::DIST_MASK_3);
    cv::Point centre;
    cv::minMaxLoc(dist, nullptr, nullptr, nullptr, &centre);
    centre -= cv::Point(1, 1);
    char area[48];
    std::snprintf(area, sizeof(area), "%.0f m2", polygonAreaM2(zones[i].polygon));
    const std::string lines[2] = {zones[i].name, area};
    int base = 0;
    const int line_h = cv::getTextSize("Ag", cv::FONT_HERSHEY_SIMPLEX, font, thickness, &base).height * 3 / 2;
    for (int k = 0; k < 2; ++k) {
      const cv::Size ts = cv::getTextSize(lines[k], cv::FONT_HERSHEY_SIMPLEX, font, thickness, &base);
      const cv::Point org(centre.x - ts.width / 2, centre.y + k * line_h);
      cv::putText(img, lines[k], org, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(255, 255, 255), thickness + 2);
      cv::putText(img, lines[k], org, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(20, 20, 20), thickness);
    }
  }
  return img;
}

void writeZonesPng(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                   const std::string& png_path, const ZoneDrawingParams& params) {
  const cv::Mat img = drawZones(grid, zones, params);
  writePngAtomically(png_path, img);
}

}  // namespace krp
