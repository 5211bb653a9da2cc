// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>
#include <vector>

#include "mrpt_krp_plugin/zones/landmarks.h"
#include "mrpt_krp_plugin/zones/zone_drawing.h"

namespace krp {

/// The zones picture with each zone's landmarks drawn in its colour and numbered in keypoint
/// order; written as PNG atomically.
void writeLandmarksPng(const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<Zone>& zones,
                       const std::vector<ZoneLandmarks>& landmarks, const std::string& png_path,
                       const ZoneDrawingParams& params = {});

}  // namespace krp
