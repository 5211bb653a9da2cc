// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>

#include <vector>

namespace krp {

/// `map`'s cells whose p(free) is above `min_freeness`, in MRPT's cell order (cy, then cx).
std::vector<cv::Point> freeCellsOf(const mrpt::maps::COccupancyGridMap2D& map, double min_freeness);

/// The free cells of one map (p(free) above a threshold), in MRPT's cell order: where the seeded
/// prior draws its uniform share. Finding them reads every cell, which on a large map costs more
/// than most of the relocalization (14 ms on the bench's warehouse, 6 ms on its office, per
/// seeding), so whoever holds a map for many seedings builds this once and hands it to each
/// SeededInitializer. It keeps a copy of the map's cells to tell whether a map is still the one
/// it was built from.
class FreeCells {
 public:
  FreeCells(const mrpt::maps::COccupancyGridMap2D& map, double min_freeness);

  const std::vector<cv::Point>& cells() const { return cells_; }
  /// Built from a map of this geometry and these very cells, with this threshold: its cells are
  /// `map`'s.
  bool describes(const mrpt::maps::COccupancyGridMap2D& map, double min_freeness) const;

 private:
  std::vector<cv::Point> cells_;
  double min_freeness_;
  std::vector<mrpt::maps::COccupancyGridMap2D::cellType> raw_;  ///< the map's cells it was built from
  size_t size_x_, size_y_;
  float resolution_, x_min_, y_min_;
};

}  // namespace krp
