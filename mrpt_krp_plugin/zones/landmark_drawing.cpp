// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/zones/landmark_drawing.h"

#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/png_file.h"

namespace krp {

void writeLandmarksPng(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                       const std::vector<ZoneLandmarks>& landmarks, const std::string& png_path,
                       const ZoneDrawingParams& params) {
  cv::Mat img = drawZones(grid, zones, params);
  const double scale = zoneDrawingScale(grid, params);
  const int radius = std::max(3, img.cols / 300);
  const double font = std::max(0.3, img.cols / 4000.0);
  for (size_t z = 0; z < landmarks.size(); ++z) {
    const cv::Scalar colour = zoneColour(z) * 0.55;
    for (size_t i = 0; i < landmarks[z].points.size(); ++i) {
      const cv::Point c = zoneDrawingPixel(grid, landmarks[z].points[i], scale);
      cv::circle(img, c, radius, cv::Scalar(255, 255, 255), cv::FILLED);
      cv::circle(img, c, radius, colour, 2);
      cv::putText(img, std::to_string(i), c + cv::Point(radius + 1, -radius - 1), cv::FONT_HERSHEY_SIMPLEX, font,
                  colour, 1);
    }
  }
  writePngAtomically(png_path, img);
}

}  // namespace krp
