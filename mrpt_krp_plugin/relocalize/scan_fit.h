// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <opencv2/core.hpp>

namespace krp {

struct ScanFitParams {
  /// A beam endpoint this close to a mapped obstacle agrees with the map: a few times the
  /// range noise plus half a map cell [m].
  double match_distance_m = 0.15;
  double min_occupancy = 0.65;  ///< a map cell with p(occupied) above this is an obstacle [0..1]
};

/// How well a scan taken at a pose agrees with the map.
struct ScanFit {
  double fit_fraction = 0.0;  ///< returns that end within match_distance of an obstacle [0..1]
  int returns = 0;            ///< beams with a return that were checked
  double mean_distance_m = 0.0;  ///< mean endpoint-to-obstacle distance, capped at 1 m [m]
};

/// Scores poses by the fraction of a scan's returns that land on mapped obstacles, from a
/// distance field of the map computed once. Unlike the filter's likelihood, the figure has a
/// meaning of its own (0.9 = nine returns in ten are explained by the map), which is what a
/// "not localized" threshold needs.
class ScanFitScorer {
 public:
  ScanFitScorer(const mrpt::maps::COccupancyGridMap2D& map, ScanFitParams params = {});

  ScanFit score(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& robot_pose) const;

 private:
  ScanFitParams params_;
  cv::Mat distance_m_;  ///< CV_32F, per map cell: distance to the nearest obstacle cell [m]
  double x_min_ = 0, y_min_ = 0, resolution_ = 0;
};

}  // namespace krp
