// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/free_cells.h"

#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {

std::vector<cv::Point> freeCellsOf(const mrpt::maps::COccupancyGridMap2D& map, double min_freeness) {
  CellClassParams p;
  p.max_free_occupancy = 1.0 - min_freeness;
  return maskedCells(freeMask(map, p));
}

FreeCells::FreeCells(const mrpt::maps::COccupancyGridMap2D& map, double min_freeness)
    : cells_(freeCellsOf(map, min_freeness)),
      min_freeness_(min_freeness),
      raw_(map.getRawMap()),
      size_x_(map.getSizeX()),
      size_y_(map.getSizeY()),
      resolution_(map.getResolution()),
      x_min_(map.getXMin()),
      y_min_(map.getYMin()) {}

bool FreeCells::describes(const mrpt::maps::COccupancyGridMap2D& map, double min_freeness) const {
  // The geometry first: comparing the cells is the costly part, though still a small share of
  // finding them again.
  return min_freeness == min_freeness_ && map.getSizeX() == size_x_ && map.getSizeY() == size_y_ &&
         map.getResolution() == resolution_ && map.getXMin() == x_min_ && map.getYMin() == y_min_ &&
         map.getRawMap() == raw_;
}

}  // namespace krp
