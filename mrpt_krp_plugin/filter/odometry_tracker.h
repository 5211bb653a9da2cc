// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <optional>

#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"

namespace krp {

struct OdometryTrackerParams {
  /// The filter updates only after the robot moved this far or turned this much since the
  /// last update (AMCL's update_min_d / update_min_a defaults), so a robot standing still does
  /// not collapse its particle cloud onto one scan's noise. The first scan always updates.
  double update_min_d_m = 0.2;
  double update_min_a_deg = 30.0;
  OdometryModelParams odometry;  ///< noise of the motion model
};

struct TrackerUpdate {
  MclEstimate estimate;             ///< robot pose in the map frame
  mrpt::math::TPose2D map_to_odom;  ///< the correction that maps the odometry frame onto the map
};

/// Tracks a robot from scans and absolute odometry poses, as a localization node receives
/// them: odometry increments between filter updates become the motion, and the estimate is
/// also given as the map -> odom correction a navigation stack expects.
class OdometryTracker {
 public:
  OdometryTracker(std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map, std::shared_ptr<ParticleInitializer> init,
                  MclParams mcl = {}, OdometryTrackerParams params = {});

  /// `odom_pose`: the robot in the odometry frame at the scan's time. Empty when the robot has
  /// not moved enough for an update (the last map -> odom correction still holds).
  std::optional<TrackerUpdate> update(const mrpt::obs::CObservation2DRangeScan::Ptr& scan,
                                      const mrpt::math::TPose2D& odom_pose);

  /// The next scan re-runs the initializer (a global relocalization).
  void reinitialize() { localizer_.reinitialize(); }

  const MclLocalizer& localizer() const { return localizer_; }
  /// The filter checks each convergence for a look-alike place (MclLocalizer::setLookAlikeGuard).
  void setLookAlikeGuard(std::shared_ptr<const LookAlikeGuard> guard) { localizer_.setLookAlikeGuard(std::move(guard)); }
  const std::optional<TrackerUpdate>& last() const { return last_; }

 private:
  OdometryTrackerParams params_;
  MclLocalizer localizer_;
  std::optional<mrpt::math::TPose2D> odom_at_last_update_;
  std::optional<TrackerUpdate> last_;
};

}  // namespace krp
