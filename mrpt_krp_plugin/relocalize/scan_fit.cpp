// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/scan_fit.h"


#include <algorithm>
#include <cmath>

#include "mrpt_krp_plugin/map/grid_image.h"
#include "mrpt_krp_plugin/submap/scan_beams.h"

namespace krp {

namespace {
// Endpoints farther than this from any obstacle count as this far in the mean: one stray
// return (a person, a door left open) must not dominate it [m].
constexpr double kMeanDistanceCapM = 1.0;
}  // namespace

ScanFitScorer::ScanFitScorer(const mrpt::maps::COccupancyGridMap2D& map, ScanFitParams params)
    : params_(params), x_min_(map.getXMin()), y_min_(map.getYMin()), resolution_(map.getResolution()) {
  CellClassParams cells;
  cells.min_occupied_occupancy = params_.min_occupancy;
  distance_m_ = obstacleDistanceByCell(map, cells) * resolution_;
}

ScanFit ScanFitScorer::score(const mrpt::obs::CObservation2DRangeScan& scan,
                             const mrpt::math::TPose2D& robot_pose) const {
  const auto beams = scanBeams(scan);
  const auto sensor = mrpt::poses::CPose2D(robot_pose) + mrpt::poses::CPose2D(scan.sensorPose);
  const double cs = std::cos(sensor.phi()), sn = std::sin(sensor.phi());
  ScanFit fit;
  int matched = 0;
  double distance_sum = 0;
  for (const auto& b : beams.beams) {
    if (!b.hit) continue;
    const double lx = b.range_m * std::cos(b.angle_rad), ly = b.range_m * std::sin(b.angle_rad);
    const double x = sensor.x() + cs * lx - sn * ly, y = sensor.y() + sn * lx + cs * ly;
    const int cx = static_cast<int>(std::floor((x - x_min_) / resolution_));
    const int cy = static_cast<int>(std::floor((y - y_min_) / resolution_));
    double d = kMeanDistanceCapM;  // a return outside the map agrees with nothing
    if (cx >= 0 && cy >= 0 && cx < distance_m_.cols && cy < distance_m_.rows)
      d = std::min<double>(distance_m_.at<float>(cy, cx), kMeanDistanceCapM);
    ++fit.returns;
    distance_sum += d;
    if (d <= params_.match_distance_m) ++matched;
  }
  if (fit.returns > 0) {
    fit.fit_fraction = static_cast<double>(matched) / fit.returns;
    fit.mean_distance_m = distance_sum / fit.returns;
  }
  return fit;
}

}  // namespace krp
