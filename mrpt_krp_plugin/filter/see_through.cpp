// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/see_through.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mrpt_krp_plugin/map/grid_image.h"
#include "mrpt_krp_plugin/submap/scan_beams.h"

namespace krp {

namespace {
// A ray point anywhere in a cell is within this many cells of the cell's centre, and an
// obstacle cell reaches as far from its own: a step this much shorter than the clearance
// cannot jump over an obstacle cell.
constexpr double kStepSafetyCells = 1.5;
// The shortest step, so that grazing a wall does not crawl [cells].
constexpr double kMinStepCells = 0.5;
// countUpTo checks every kInterleave-th beam first, then the ones after them, and so on.
constexpr size_t kInterleave = 8;
// Rays marched side by side by countCrossing: enough to cover a clearance lookup's latency
// (an L2 access and the step's arithmetic), few enough to stay in registers.
constexpr int kLanes = 8;

// The map's clearance per cell, in cells (SeeThroughPenalty::clearance_cells_).
struct ClearanceField {
  const float* at;
  int cols, rows;
};

enum class RayStep { kGoesOn, kClear, kCrossed };

// One step of a ray from (gx0, gy0) along (c, s), `t` cells along it so far, `length` cells long
// [cells]: a ray leaving the map counts as clear. Both marches take their steps here, so that
// each ray takes bit for bit the same steps in either.
inline RayStep marchStep(const ClearanceField& field, double gx0, double gy0, double c, double s, double length,
                         double& t) {
  if (!(t < length)) return RayStep::kClear;
  const double gx = gx0 + t * c, gy = gy0 + t * s;
  if (gx < 0.0 || gy < 0.0) return RayStep::kClear;
  const int cx = static_cast<int>(gx), cy = static_cast<int>(gy);
  if (cx >= field.cols || cy >= field.rows) return RayStep::kClear;
  const double clearance = field.at[static_cast<size_t>(cy) * field.cols + cx];
  if (clearance <= 0.0) return RayStep::kCrossed;
  t += std::max(clearance - kStepSafetyCells, kMinStepCells);
  return RayStep::kGoesOn;
}
}  // namespace

double seeThroughNats(const SensorModelParams& sensor) {
  // MRPT's likelihood field: zRandom / LF_maxRange + zHit * exp(-d^2 / 2 sigma^2), with d capped
  // at LF_maxCorrsDistance; LF_maxRange is left at MRPT's default by useSensorModel.
  const double random_term = sensor.z_random / mrpt::maps::COccupancyGridMap2D::TLikelihoodOptions().LF_maxRange;
  const double d = sensor.max_corr_distance_m, s = sensor.std_hit_m;
  const double on_obstacle = random_term + sensor.z_hit;
  const double far_away = random_term + sensor.z_hit * std::exp(-d * d / (2.0 * s * s));
  return std::log(on_obstacle) - std::log(far_away);
}

SeeThroughPenalty::SeeThroughPenalty(const mrpt::maps::COccupancyGridMap2D& map, const SensorModelParams& sensor,
                                     SeeThroughParams params)
    : params_(params),
      decimation_(std::max(1, sensor.decimation)),
      per_beam_nats_(seeThroughNats(sensor)),
      x_min_(map.getXMin()),
      y_min_(map.getYMin()),
      resolution_(map.getResolution()) {
  if (!(params_.tolerance_m >= 0.0)) throw std::invalid_argument("SeeThroughPenalty: tolerance_m must be >= 0");
  if (!(params_.min_occupancy > 0.0 && params_.min_occupancy < 1.0))
    throw std::invalid_argument("SeeThroughPenalty: min_occupancy must be in (0, 1)");
  CellClassParams cells;
  cells.min_occupied_occupancy = params_.min_occupancy;
  clearance_cells_ = obstacleDistanceByCell(map, cells);
}

bool SeeThroughPenalty::crossesObstacle(double x0, double y0, double cos_a, double sin_a, double length_m) const {
  // In cell units, so that a step is one multiply-add and a cell index a truncation.
  const double gx0 = (x0 - x_min_) / resolution_, gy0 = (y0 - y_min_) / resolution_;
  const double length = length_m / resolution_;
  const ClearanceField field{clearance_cells_.ptr<float>(0), clearance_cells_.cols, clearance_cells_.rows};
  double t = 0.0;
  RayStep step;
  while ((step = marchStep(field, gx0, gy0, cos_a, sin_a, length, t)) == RayStep::kGoesOn) {
  }
  return step == RayStep::kCrossed;
}

int SeeThroughPenalty::countCrossing(const Scan& scan, const mrpt::poses::CPose2D& sensor, int enough) const {
  // The same expressions as crossesObstacle, so that each ray starts from the same numbers.
  const double gx0 = (sensor.x() - x_min_) / resolution_, gy0 = (sensor.y() - y_min_) / resolution_;
  const double cs = std::cos(sensor.phi()), sn = std::sin(sensor.phi());
  const ClearanceField field{clearance_cells_.ptr<float>(0), clearance_cells_.cols, clearance_cells_.rows};
  const size_t n = scan.order_.size();
  struct Lane {
    double t, c, s, length;
  };
  Lane lanes[kLanes];
  int active = 0, found = 0;
  size_t next = 0;
  // A lane whose ray ended takes the next ray in the scan's order.
  auto load = [&](Lane& lane) {
    const size_t i = scan.order_[next++];
    lane.c = cs * scan.cos_angle_[i] - sn * scan.sin_angle_[i];
    lane.s = sn * scan.cos_angle_[i] + cs * scan.sin_angle_[i];
    lane.length = scan.clear_length_m_[i] / resolution_;
    lane.t = 0.0;
  };
  while (active < kLanes && next < n) load(lanes[active++]);
  while (active > 0) {
    if (found >= enough) return enough;
    for (int k = 0; k < active; ++k) {
      Lane& lane = lanes[k];
      const RayStep step = marchStep(field, gx0, gy0, lane.c, lane.s, lane.length, lane.t);
      if (step == RayStep::kGoesOn) continue;
      found += step == RayStep::kCrossed ? 1 : 0;
      if (next < n)
        load(lane);  // the new ray takes its first step in the next round
      else
        lanes[k] = lanes[--active];  // the lane moved here steps in the next round
    }
  }
  return std::min(found, enough);
}

SeeThroughPenalty::Scan SeeThroughPenalty::forScan(const mrpt::obs::CObservation2DRangeScan& scan) const {
  const auto beams = scanBeams(scan);
  Scan out;
  out.penalty_ = this;
  out.sensor_on_robot_ = mrpt::poses::CPose2D(scan.sensorPose);
  for (size_t i = 0; i < beams.beams.size(); i += static_cast<size_t>(decimation_)) {
    const auto& b = beams.beams[i];
    if (!b.hit || b.range_m <= params_.tolerance_m) continue;
    out.cos_angle_.push_back(std::cos(b.angle_rad));
    out.sin_angle_.push_back(std::sin(b.angle_rad));
    out.clear_length_m_.push_back(b.range_m - params_.tolerance_m);
  }
  // Every kInterleave-th beam first, then the ones after them: the beams that see through come
  // in runs (a doorway, the gap between two racks), and a count that may stop early finds them sooner.
  for (size_t first = 0; first < kInterleave; ++first)
    for (size_t i = first; i < out.clear_length_m_.size(); i += kInterleave) out.order_.push_back(i);
  return out;
}

int SeeThroughPenalty::Scan::countUpTo(const mrpt::math::TPose2D& robot_pose, int enough) const {
  // Checking ray by ray and stopping at `enough` returns min(count, enough), whatever the order.
  if (enough <= 0) return 0;
  return penalty_->countCrossing(*this, mrpt::poses::CPose2D(robot_pose) + sensor_on_robot_, enough);
}

int SeeThroughPenalty::Scan::countOneRayAtATime(const mrpt::math::TPose2D& robot_pose) const {
  const auto sensor = mrpt::poses::CPose2D(robot_pose) + sensor_on_robot_;
  const double cs = std::cos(sensor.phi()), sn = std::sin(sensor.phi());
  int seen_through = 0;
  for (const size_t i : order_) {
    const double c = cs * cos_angle_[i] - sn * sin_angle_[i];
    const double s = sn * cos_angle_[i] + cs * sin_angle_[i];
    if (penalty_->crossesObstacle(sensor.x(), sensor.y(), c, s, clear_length_m_[i])) ++seen_through;
  }
  return seen_through;
}

double SeeThroughPenalty::Scan::shareUpTo(const mrpt::math::TPose2D& robot_pose, double enough) const {
  if (clear_length_m_.empty()) return 0.0;
  const double n = static_cast<double>(clear_length_m_.size());
  const int enough_count = static_cast<int>(std::ceil(std::max(0.0, enough) * n));
  return countUpTo(robot_pose, enough_count) / n;
}

}  // namespace krp
