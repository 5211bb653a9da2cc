// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>

#include "mrpt_krp_plugin/submap/local_grid.h"

namespace krp {

/// Grey levels of the zone classifier's input image (the thesis's occupancy submap).
struct OccupancyImageLevels {
  uint8_t free = 255;      ///< known free: white
  uint8_t unknown = 128;   ///< not seen: mid grey
  uint8_t occupied = 0;    ///< obstacle: black
};

/// The zone classifier's input: one grey channel, row 0 ahead of the robot.
cv::Mat renderOccupancyImage(const LocalGrid& grid, const OccupancyImageLevels& levels = {});

}  // namespace krp
