// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace krp {

/// A named region of the map: a simple polygon in grid-frame metres.
struct Zone {
  std::string name;
  std::vector<mrpt::math::TPoint2D> polygon;
};

/// Per-cell zone index (CV_32S, row 0 at the top, -1 = no zone), from filling each polygon.
/// Filling includes the cells the outline passes through, so a zone made from a region's
/// boundary cells covers the whole region.
cv::Mat rasterizeZones(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones);

/// Looks zones up by point through their rasterization.
class ZoneIndex {
 public:
  ZoneIndex(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones);
  /// Index of the zone holding the point, or -1.
  int zoneAt(const mrpt::math::TPoint2D& p) const;
  const cv::Mat& labels() const { return labels_; }

 private:
  const mrpt::maps::COccupancyGridMap2D& grid_;
  cv::Mat labels_;
};

/// Polygon area in m^2 (shoelace formula; absolute value).
double polygonAreaM2(const std::vector<mrpt::math::TPoint2D>& polygon);

}  // namespace krp
