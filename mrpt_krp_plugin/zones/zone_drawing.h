// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/zones/zone.h"

namespace krp {

struct ZoneDrawingParams {
  double fill_opacity = 0.35;   ///< zone tint over the map [0..1]
  int min_image_width_px = 800; ///< small maps are scaled up to at least this width
  int max_image_width_px = 2400; ///< large maps are scaled down to at most this width
};

/// The map in grey with each zone tinted, outlined and labelled with its name and area.
cv::Mat drawZones(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                  const ZoneDrawingParams& params = {});

/// Draws and writes a PNG atomically.
void writeZonesPng(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                   const std::string& png_path, const ZoneDrawingParams& params = {});

/// Image pixels per map cell in drawZones' picture.
double zoneDrawingScale(const mrpt::maps::COccupancyGridMap2D& grid, const ZoneDrawingParams& params = {});

/// Where a map point falls in drawZones' picture.
cv::Point zoneDrawingPixel(const mrpt::maps::COccupancyGridMap2D& grid, const mrpt::math::TPoint2D& p, double scale);

/// A distinct colour for index i (BGR), shared by every picture that colours zones.
cv::Scalar zoneColour(size_t i);

}  // namespace krp
