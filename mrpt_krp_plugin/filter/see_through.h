// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <opencv2/core.hpp>

#include <vector>

#include "mrpt_krp_plugin/filter/sensor_model.h"

namespace krp {

/// The likelihood field scores a beam only where it ends. At a wrong pose, a beam that in truth
/// went through a doorway ends on the wall beyond the one the map puts in its way, and scores
/// as a hit; look-alike rooms often differ only by such doorways, and unmapped clutter can then
/// make the wrong room fit the endpoints better. A lidar cannot see through a wall: a return
/// from well beyond a mapped obstacle on its ray is evidence against the pose. (Clutter only
/// shortens returns, so it never makes the right pose see through the map; a door mapped
/// closed that stands open does, which is why this is a penalty and not a veto.)
struct SeeThroughParams {
  /// Off: the filter weighs particles with the likelihood field alone, as amcl does.
  bool enabled = true;
  /// A beam sees through the map when a mapped obstacle lies on its ray nearer than its return
  /// by more than this: range noise and the map's rasterization stay well below it [m].
  double tolerance_m = 0.3;
  double min_occupancy = 0.65;  ///< a map cell with p(occupied) above this is an obstacle [0..1]
};

/// Counts a scan's see-through beams at a pose by marching each beam's ray over a distance
/// field of the map (steps as long as the clearance allows), and turns them into the
/// log-likelihood penalty the filter and the look-alike guard add to the likelihood field's.
class SeeThroughPenalty {
 public:
  /// `sensor`: the filter's likelihood field; its decimation is used here too, and a
  /// see-through beam costs what a beam that matches nothing costs there (seeThroughNats).
  /// Throws std::invalid_argument for a tolerance that is negative or an occupancy outside (0, 1).
  SeeThroughPenalty(const mrpt::maps::COccupancyGridMap2D& map, const SensorModelParams& sensor,
                    SeeThroughParams params = {});

  /// One scan's checked beams (every sensor.decimation-th with a return), read once and charged
  /// at as many poses as needed: a filter update weighs every particle and the guard's places
  /// with the same scan. Valid while the SeeThroughPenalty that made it lives.
  class Scan {
   public:
    /// Checked beams whose ray crosses a mapped obstacle more than tolerance_m before the
    /// return. Rays leaving the map count as clear.
    int count(const mrpt::math::TPose2D& robot_pose) const { return countUpTo(robot_pose, checked()); }
    /// count(), but it may stop once it has found `enough` (and then returns at least that): a
    /// search that only needs to know whether a place sees through too much stops early. The
    /// beams are checked spread over the scan, not in angle order, because the beams that see
    /// through come in runs (a doorway, the gap between two racks).
    int countUpTo(const mrpt::math::TPose2D& robot_pose, int enough) const;
    /// count(), each ray marched to its end before the next is started: the same answer, and
    /// the reference the faster count() is checked and timed against (krp-bench-see-through).
    int countOneRayAtATime(const mrpt::math::TPose2D& robot_pose) const;
    int checked() const { return static_cast<int>(clear_length_m_.size()); }
    /// count() times seeThroughNats(): what to subtract from the pose's log-likelihood [nats].
    double nats(const mrpt::math::TPose2D& robot_pose) const { return penalty_->per_beam_nats_ * count(robot_pose); }
    /// count() over the beams checked: the share of the scan's returns that see through [0..1].
    double share(const mrpt::math::TPose2D& robot_pose) const { return shareUpTo(robot_pose, 1.0); }
    /// share(), stopping as countUpTo does once it reaches `enough` [0..1].
    double shareUpTo(const mrpt::math::TPose2D& robot_pose, double enough) const;

   private:
    friend class SeeThroughPenalty;
    const SeeThroughPenalty* penalty_ = nullptr;
    mrpt::poses::CPose2D sensor_on_robot_;
    std::vector<double> cos_angle_, sin_angle_, clear_length_m_;  ///< ray direction, length that must be clear
    std::vector<size_t> order_;  ///< the beams in the order they are checked, spread over the scan
  };
  Scan forScan(const mrpt::obs::CObservation2DRangeScan& scan) const;

  /// Scan::count and Scan::nats for a scan charged at one pose only.
  int count(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& robot_pose) const {
    return forScan(scan).count(robot_pose);
  }
  double nats(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& robot_pose) const {
    return forScan(scan).nats(robot_pose);
  }
  double perBeamNats() const { return per_beam_nats_; }

 private:
  bool crossesObstacle(double x0, double y0, double cos_a, double sin_a, double length_m) const;
  /// How many of `scan`'s rays from `sensor` cross an obstacle, as crossesObstacle says ray by
  /// ray, stopping once `enough` are found: several rays are marched side by side, so that one
  /// ray's wait for its next clearance cell overlaps the others' (each step of a ray depends on
  /// the cell its last step reached). Every ray takes the same steps as in crossesObstacle.
  int countCrossing(const Scan& scan, const mrpt::poses::CPose2D& sensor, int enough) const;

  SeeThroughParams params_;
  int decimation_ = 1;
  double per_beam_nats_ = 0.0;
  cv::Mat clearance_cells_;  ///< CV_32F, continuous, per map cell (row = cell y): distance to the nearest obstacle cell [cells]
  double x_min_ = 0, y_min_ = 0, resolution_ = 0;
};

/// The log-likelihood gap, in MRPT's likelihood field with `sensor`, between a beam ending on a
/// mapped obstacle and one ending far from any (at or beyond max_corr_distance_m): what a beam
/// that matches nothing costs [nats].
double seeThroughNats(const SensorModelParams& sensor);

}  // namespace krp
