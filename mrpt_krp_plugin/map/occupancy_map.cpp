// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/occupancy_map.h"

#include <cmath>

namespace krp {

mrpt::math::TPose2D OccupancyMap::toSourceFrame(const mrpt::math::TPose2D& p) const {
  if (!grid) return p;
  // map_server rotates the image about the origin point (x_min, y_min) of the grid.
  const double ox = grid->getXMin(), oy = grid->getYMin();
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  const double dx = p.x - ox, dy = p.y - oy;
  return {ox + c * dx - s * dy, oy + s * dx + c * dy, mrpt::math::wrapToPi(p.phi + yaw_rad)};
}

mrpt::math::TPose2D OccupancyMap::toGridFrame(const mrpt::math::TPose2D& p) const {
  if (!grid) return p;
  const double ox = grid->getXMin(), oy = grid->getYMin();
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  const double dx = p.x - ox, dy = p.y - oy;
  return {ox + c * dx + s * dy, oy - s * dx + c * dy, mrpt::math::wrapToPi(p.phi - yaw_rad)};
}

double occupancyFromGridValue(int value) {
  return (value >= 0 && value <= 100) ? value / 100.0 : kUnknownOccupancy;
}

std::size_t countFreeCells(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p) {
  std::size_t n = 0;
  for (unsigned y = 0; y < grid.getSizeY(); ++y)
    for (unsigned x = 0; x < grid.getSizeX(); ++x)
      if (1.0 - grid.getCell(x, y) < p.max_free_occupancy) ++n;
  return n;
}

double freeAreaM2(const mrpt::maps::COccupancyGridMap2D& grid, const CellClassParams& p) {
  const double r = grid.getResolution();
  return static_cast<double>(countFreeCells(grid, p)) * r * r;
}

}  // namespace krp
