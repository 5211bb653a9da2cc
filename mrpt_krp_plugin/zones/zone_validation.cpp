// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/zones/zone_validation.h"

#include <opencv2/imgproc.hpp>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {

std::vector<std::string> findZoneProblems(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                                          const ZoneValidationParams& params) {
  std::vector<std::string> problems;
  if (zones.empty()) return {"the zone list is empty"};
  const double cell_area = grid.getResolution() * grid.getResolution();
  const cv::Mat free = freeMask(grid, params.cells);
  cv::Mat claims = cv::Mat::zeros(free.size(), CV_32S);
  const double eps = 1e-6;
  for (const auto& z : zones) {
    if (z.polygon.size() < 3) {
      problems.push_back("zone '" + z.name + "' has fewer than 3 points");
      continue;
    }
    for (const auto& p : z.polygon) {
      if (p.x < grid.getXMin() - eps || p.x > grid.getXMax() + eps || p.y < grid.getYMin() - eps ||
          p.y > grid.getYMax() + eps) {
        std::ostringstream o;
        o << "zone '" << z.name << "' has point (" << p.x << ", " << p.y << ") outside the map [" << grid.getXMin()
          << ", " << grid.getXMax() << "] x [" << grid.getYMin() << ", " << grid.getYMax() << "]";
        problems.push_back(o.str());
        break;
      }
    }
    cv::Mat mask = cv::Mat::zeros(free.size(), CV_8U);
    std::vector<cv::Point> px;
    for (const auto& p : z.polygon) px.push_back(worldToPixel(grid, p));
    cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{px}, cv::Scalar(1));
    cv::Mat zone_free;
    cv::bitwise_and(mask, free / 255, zone_free);
    const double free_m2 = cv::countNonZero(zone_free) * cell_area;
    if (free_m2 < params.min_free_area_m2) {
      std::ostringstream o;
      o << "zone '" << z.name << "' holds " << free_m2 << " m^2 of free space (minimum " << params.min_free_area_m2
        << ")";
      problems.push_back(o.str());
    }
    cv::Mat zf32;
    zone_free.convertTo(zf32, CV_32S);
    claims += zf32;
  }
  const double overlap_m2 = cv::countNonZero(claims > 1) * cell_area;
  if (overlap_m2 > params.max_overlap_free_m2) {
    std::ostringstream o;
    o << "zones overlap on " << overlap_m2 << " m^2 of free space";
    problems.push_back(o.str());
  }
  return problems;
}

void validateZones(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                   const std::string& source, const ZoneValidationParams& params) {
  const auto problems = findZoneProblems(grid, zones, params);
  if (problems.empty()) return;
  std::string all;
  for (const auto& p : problems) all += (all.empty() ? "" : "; ") + p;
  throw InputError(source, all);
}

}  // namespace krp
