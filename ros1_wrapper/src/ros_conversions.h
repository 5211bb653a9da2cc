// SPDX-License-Identifier: BSD-3-Clause
// Message <-> library type conversions. No state, no ROS node: unit-testable without a roscore.
#pragma once

#include <string>

#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <sensor_msgs/LaserScan.h>
#include <visualization_msgs/MarkerArray.h>

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include "mrpt_krp_plugin/map/map_sanity.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_ranking.h"

namespace krp::ros1 {

/// An OccupancyGrid as the library's map. The grid frame is the message's origin cell; a yawed
/// origin is kept in `yaw_rad` (poses are turned back with OccupancyMap::toSourceFrame).
/// InputError for an empty grid, a bad resolution or origin (see MapSanityLimits), or data of the
/// wrong size.
OccupancyMap occupancyMapFromRos(const nav_msgs::OccupancyGrid& msg, const MapSanityLimits& limits = {});

struct ScanCheck {
  int min_valid_returns = 10;  ///< fewer finite in-range returns than this: the scan is unusable
};

/// A LaserScan as MRPT's scan, with the sensor at `laser_in_base` on the robot. InputError
/// (naming the frame and the problem) for non-finite or inconsistent angles, a beam count that
/// does not match the angle range, a bad max range, or too few usable returns. NaN, inf,
/// negative and out-of-range readings become "no return" beams.
mrpt::obs::CObservation2DRangeScan::Ptr scanFromRos(const sensor_msgs::LaserScan& msg,
                                                    const mrpt::poses::CPose3D& laser_in_base,
                                                    const ScanCheck& check = {});

/// MRPT's scan as a LaserScan in `frame_id` (the sensor pose is not part of it: publish it on tf).
/// "No return" beams become +inf, as REP 117 asks.
sensor_msgs::LaserScan scanToRos(const mrpt::obs::CObservation2DRangeScan& scan, const ros::Time& stamp,
                                 const std::string& frame_id);

/// A planar pose from a ROS pose (yaw from the quaternion; roll and pitch ignored).
mrpt::math::TPose2D pose2DFromRos(const geometry_msgs::Pose& pose);
mrpt::math::TPose2D pose2DFromRos(const geometry_msgs::Transform& tf);
geometry_msgs::Pose poseToRos(const mrpt::math::TPose2D& pose);

/// `child` at planar `pose` in `parent`, as a tf message stamped `stamp`.
geometry_msgs::TransformStamped transformToRos(const mrpt::math::TPose2D& pose, const std::string& parent,
                                               const std::string& child, const ros::Time& stamp);

/// The (x, y, yaw) covariance placed in ROS's 6x6 (x, y, z, roll, pitch, yaw) row-major
/// layout: yaw variance at index 35, as AMCL reads it.
boost::array<double, 36> covarianceToRos(const mrpt::math::CMatrixDouble33& cov);

/// The inverse of covarianceToRos, turned from the map frame into a grid frame yawed by
/// `grid_yaw_rad`. Non-finite or negative variances are replaced by AMCL's initial defaults.
mrpt::math::CMatrixDouble33 covarianceFromRos(const boost::array<double, 36>& cov, double grid_yaw_rad);

/// The ranking's best hypothesis as an `initialpose` message in the map frame.
geometry_msgs::PoseWithCovarianceStamped initialPoseMsg(const PoseHypothesis& best, const OccupancyMap& map,
                                                        const std_msgs::Header& header);

/// All hypotheses (best first) for RViz.
geometry_msgs::PoseArray hypothesesPoseArray(const Ranking& ranking, const OccupancyMap& map,
                                             const std_msgs::Header& header);

/// One arrow per hypothesis, coloured and sized by confidence, with its confidence as text;
/// starts with a DELETEALL so stale hypotheses disappear.
visualization_msgs::MarkerArray hypothesesMarkers(const Ranking& ranking, const OccupancyMap& map,
                                                  const std_msgs::Header& header);

}  // namespace krp::ros1
