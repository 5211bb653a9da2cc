// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/odometry_tracker.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

OdometryTracker::OdometryTracker(std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map,
                                 std::shared_ptr<ParticleInitializer> init, MclParams mcl, OdometryTrackerParams params)
    : params_(params), localizer_(std::move(map), std::move(init), mcl) {
  if (!(params_.update_min_d_m >= 0) || !(params_.update_min_a_deg >= 0))
    throw InputError("odometry tracker", "update_min_d_m and update_min_a_deg must be >= 0");
}

std::optional<TrackerUpdate> OdometryTracker::update(const mrpt::obs::CObservation2DRangeScan::Ptr& scan,
                                                     const mrpt::math::TPose2D& odom_pose) {
  if (!scan) throw InputError("odometry tracker", "no scan");
  const mrpt::poses::CPose2D odom_now(odom_pose);
  mrpt::poses::CPose2D motion(0, 0, 0);
  if (odom_at_last_update_) motion = odom_now - mrpt::poses::CPose2D(*odom_at_last_update_);
  const bool moved_enough = motion.norm() >= params_.update_min_d_m ||
                            std::abs(mrpt::math::wrapToPi(motion.phi())) >= params_.update_min_a_deg * M_PI / 180.0;
  if (localizer_.isInitialized() && !moved_enough) return std::nullopt;

  TrackerUpdate u;
  u.estimate = localizer_.update(makeRawlogStep(motion, scan, params_.odometry));
  // map <- odom = (map <- base) * (odom <- base)^-1
  u.map_to_odom = (mrpt::poses::CPose2D(u.estimate.mean) + (mrpt::poses::CPose2D() - odom_now)).asTPose();
  odom_at_last_update_ = odom_pose;
  last_ = u;
  return u;
}

}  // namespace krp
