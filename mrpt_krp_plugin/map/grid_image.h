// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>
#include <opencv2/core.hpp>

#include "mrpt_krp_plugin/map/occupancy_map.h"

namespace krp {

// The one place where the grid frame (x right, y up, metres) meets image coordinates
// (column right, row 0 at the top, pixels). Every image the project writes or reads of a
// map goes through these functions.

/// Pixel (column, row) whose cell contains the metric point; may be outside the image.
cv::Point worldToPixel(const mrpt::maps::COccupancyGridMap2D& grid, const mrpt::math::TPoint2D& p);

/// Metric centre of the cell drawn at pixel (column, row).
mrpt::math::TPoint2D pixelToWorld(const mrpt::maps::COccupancyGridMap2D& grid, const cv::Point2d& px);

/// p(occupied) as 8-bit grey, 0 = occupied (black), 255 = free (white), row 0 at the top.
cv::Mat gridToGrey(const mrpt::maps::COccupancyGridMap2D& grid);

/// 255 where the cell is free, 0 elsewhere (row 0 at the top).
cv::Mat freeMask(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p = {});

/// Per cell, the distance to the nearest non-free cell [m] (CV_32F, row 0 at the top): how
/// much room a robot or an object has there.
cv::Mat freeClearanceM(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p = {});

/// 255 where the cell is occupied, 0 elsewhere (row 0 at the top).
cv::Mat occupiedMask(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p = {});

/// Per map cell, the distance to the nearest occupied cell [cells] (CV_32F, exact L2), indexed
/// (cy, cx) as MRPT indexes cells, row 0 at the bottom unlike the images above: the lookup table
/// of code that walks the grid in map coordinates (scan fit, see-through rays).
cv::Mat obstacleDistanceByCell(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p = {});

/// The map cell indices (x = column cx, y = row cy, y up as in MRPT) where a mask drawn by
/// freeMask() or occupiedMask() is set, in MRPT's cell order (cy, then cx).
std::vector<cv::Point> maskedCells(const cv::Mat& mask);

}  // namespace krp
