// SPDX-License-Identifier: BSD-3-Clause
#include "ros_conversions.h"

#include <Eigen/Dense>  // MRPT matrix products need it in the calling file
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp::ros1 {

namespace {
// Rotating the frame by `yaw_rad` leaves the yaw variance unchanged; the xy block turns with it.
mrpt::math::CMatrixDouble33 rotateCovarianceXy(const mrpt::math::CMatrixDouble33& cov, double yaw_rad) {
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  mrpt::math::CMatrixDouble33 rot;
  rot.setIdentity();
  rot(0, 0) = c, rot(0, 1) = -s, rot(1, 0) = s, rot(1, 1) = c;
  return mrpt::math::CMatrixDouble33(rot.asEigen() * cov.asEigen() * rot.asEigen().transpose());
}

// Beam spacing may disagree with (angle_max - angle_min) / increment by float rounding.
constexpr double kBeamCountTolerance = 0.01;
// The longest arrow, for a hypothesis of confidence 1 [m].
constexpr double kMarkerMaxLengthM = 1.0;
// AMCL's initial_cov_xx / initial_cov_aa defaults, for a pose given without a usable covariance.
constexpr double kDefaultStdXyM = 0.5;
constexpr double kDefaultStdYawRad = M_PI / 12;
}  // namespace

OccupancyMap occupancyMapFromRos(const nav_msgs::OccupancyGrid& msg, const MapSanityLimits& limits) {
  const std::string what = "map '" + msg.header.frame_id + "'";
  const auto& info = msg.info;
  if (msg.data.size() != static_cast<size_t>(info.width) * info.height) {
    std::ostringstream s;
    s << "data has " << msg.data.size() << " cells, width x height is " << info.width * info.height;
    throw InputError(what, s.str());
  }
  const auto& o = info.origin;
  checkGridGeometry({o.position.x, o.position.y, info.resolution, static_cast<double>(info.width),
                     static_cast<double>(info.height)},
                    limits, what);
  const double yaw = pose2DFromRos(o).phi;
  if (!std::isfinite(yaw)) throw InputError(what, "origin orientation must be finite");

  auto grid = std::make_shared<mrpt::maps::COccupancyGridMap2D>();
  grid->setSize(o.position.x, o.position.x + info.width * info.resolution, o.position.y,
                o.position.y + info.height * info.resolution, info.resolution, static_cast<float>(kUnknownOccupancy));
  for (unsigned y = 0; y < info.height; ++y)
    for (unsigned x = 0; x < info.width; ++x)
      grid->setCell(x, y, static_cast<float>(1.0 - occupancyFromGridValue(msg.data[static_cast<size_t>(y) * info.width + x])));
  if (countFreeCells(*grid) == 0) throw InputError(what, "the map has no free cell");
  return OccupancyMap{grid, yaw, "topic " + what};
}

mrpt::obs::CObservation2DRangeScan::Ptr scanFromRos(const sensor_msgs::LaserScan& msg,
                                                    const mrpt::poses::CPose3D& laser_in_base,
                                                    const ScanCheck& check) {
  const std::string what = "scan from '" + msg.header.frame_id + "'";
  if (msg.ranges.size() < 2) throw InputError(what, "fewer than 2 beams");
  if (!std::isfinite(msg.angle_min) || !std::isfinite(msg.angle_max) || !std::isfinite(msg.angle_increment) ||
      msg.angle_increment == 0.0f)
    throw InputError(what, "angle_min, angle_max and angle_increment must be finite, the increment non-zero");
  const double span = static_cast<double>(msg.angle_max) - msg.angle_min;
  const double expected_beams = span / msg.angle_increment + 1.0;
  if (!(expected_beams > 1.0) || std::abs(expected_beams - static_cast<double>(msg.ranges.size())) >
                                     kBeamCountTolerance * msg.ranges.size() + 1.0) {
    std::ostringstream s;
    s << msg.ranges.size() << " ranges, but the angles give " << expected_beams << " beams";
    throw InputError(what, s.str());
  }
  if (!(msg.range_max > 0) || !std::isfinite(msg.range_max)) throw InputError(what, "range_max must be finite and > 0");

  // MRPT's scans are centred on the sensor's x axis and spaced aperture/(N-1): an asymmetric
  // ROS scan becomes a symmetric one on a sensor turned by the centre angle.
  const size_t n = msg.ranges.size();
  const double spacing = span / static_cast<double>(n - 1);
  const double centre = msg.angle_min + 0.5 * span;
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->sensorLabel = msg.header.frame_id;
  scan->aperture = static_cast<float>(std::abs(spacing) * (n - 1));
  scan->rightToLeft = spacing > 0;
  scan->maxRange = msg.range_max;
  scan->sensorPose = laser_in_base + mrpt::poses::CPose3D(0, 0, 0, centre, 0, 0);
  scan->resizeScan(n);
  int valid = 0;
  for (size_t i = 0; i < n; ++i) {
    const float r = msg.ranges[i];
    const bool ok = std::isfinite(r) && r >= msg.range_min && r < msg.range_max && r > 0.0f;
    scan->setScanRange(i, ok ? r : msg.range_max);
    scan->setScanRangeValidity(i, ok);
    valid += ok ? 1 : 0;
  }
  if (valid < check.min_valid_returns) {
    std::ostringstream s;
    s << "only " << valid << " of " << n << " readings are usable returns (need " << check.min_valid_returns << ")";
    throw InputError(what, s.str());
  }
  return scan;
}

sensor_msgs::LaserScan scanToRos(const mrpt::obs::CObservation2DRangeScan& s, const ros::Time& stamp,
                                 const std::string& frame_id) {
  sensor_msgs::LaserScan m;
  m.header.stamp = stamp;
  m.header.frame_id = frame_id;
  const size_t n = s.getScanSize();
  const float step = n > 1 ? s.aperture / static_cast<float>(n - 1) : 0.0f;
  // MRPT's beams are symmetric about the sensor's x axis, listed right to left or left to right.
  m.angle_min = (s.rightToLeft ? -0.5f : 0.5f) * s.aperture;
  m.angle_increment = s.rightToLeft ? step : -step;
  m.angle_max = m.angle_min + m.angle_increment * static_cast<float>(n > 0 ? n - 1 : 0);
  m.range_min = 0.0f;
  m.range_max = s.maxRange;
  m.ranges.reserve(n);
  for (size_t i = 0; i < n; ++i)
    m.ranges.push_back(s.getScanRangeValidity(i) ? s.getScanRange(i) : std::numeric_limits<float>::infinity());
  return m;
}

mrpt::math::TPose2D pose2DFromRos(const geometry_msgs::Pose& pose) {
  tf2::Quaternion q(pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w);
  if (q.length2() == 0.0) q = tf2::Quaternion::getIdentity();
  return {pose.position.x, pose.position.y, tf2::getYaw(q.normalized())};
}

mrpt::math::TPose2D pose2DFromRos(const geometry_msgs::Transform& tf) {
  geometry_msgs::Pose p;
  p.position.x = tf.translation.x;
  p.position.y = tf.translation.y;
  p.orientation = tf.rotation;
  return pose2DFromRos(p);
}

geometry_msgs::Pose poseToRos(const mrpt::math::TPose2D& pose) {
  geometry_msgs::Pose p;
  p.position.x = pose.x;
  p.position.y = pose.y;
  tf2::Quaternion q;
  q.setRPY(0, 0, pose.phi);
  p.orientation.x = q.x();
  p.orientation.y = q.y();
  p.orientation.z = q.z();
  p.orientation.w = q.w();
  return p;
}

geometry_msgs::TransformStamped transformToRos(const mrpt::math::TPose2D& pose, const std::string& parent,
                                               const std::string& child, const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  const auto p = poseToRos(pose);
  t.transform.translation.x = p.position.x;
  t.transform.translation.y = p.position.y;
  t.transform.rotation = p.orientation;
  return t;
}

boost::array<double, 36> covarianceToRos(const mrpt::math::CMatrixDouble33& cov) {
  boost::array<double, 36> out{};
  const int index[3] = {0, 1, 5};  // x, y, yaw in (x, y, z, roll, pitch, yaw)
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[index[r] * 6 + index[c]] = cov(r, c);
  return out;
}

mrpt::math::CMatrixDouble33 covarianceFromRos(const boost::array<double, 36>& cov, double grid_yaw_rad) {
  const int index[3] = {0, 1, 5};
  mrpt::math::CMatrixDouble33 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = cov[index[r] * 6 + index[c]];
  const double defaults[3] = {kDefaultStdXyM * kDefaultStdXyM, kDefaultStdXyM * kDefaultStdXyM,
                              kDefaultStdYawRad * kDefaultStdYawRad};
  for (int i = 0; i < 3; ++i) {
    bool finite = true;
    for (int c = 0; c < 3; ++c) finite = finite && std::isfinite(m(i, c));
    if (!finite || !(m(i, i) > 0)) {
      for (int c = 0; c < 3; ++c) m(i, c) = m(c, i) = 0.0;
      m(i, i) = defaults[i];
    }
  }
  return rotateCovarianceXy(m, -grid_yaw_rad);
}

geometry_msgs::PoseWithCovarianceStamped initialPoseMsg(const PoseHypothesis& best, const OccupancyMap& map,
                                                        const std_msgs::Header& header) {
  geometry_msgs::PoseWithCovarianceStamped m;
  m.header = header;
  m.pose.pose = poseToRos(map.toSourceFrame(best.pose));
  m.pose.covariance = covarianceToRos(rotateCovarianceXy(best.cov, map.yaw_rad));
  return m;
}

geometry_msgs::PoseArray hypothesesPoseArray(const Ranking& ranking, const OccupancyMap& map,
                                             const std_msgs::Header& header) {
  geometry_msgs::PoseArray a;
  a.header = header;
  for (const auto& h : ranking.hypotheses) a.poses.push_back(poseToRos(map.toSourceFrame(h.pose)));
  return a;
}

visualization_msgs::MarkerArray hypothesesMarkers(const Ranking& ranking, const OccupancyMap& map,
                                                  const std_msgs::Header& header) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker clear;
  clear.header = header;
  clear.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(clear);
  int id = 0;
  for (const auto& h : ranking.hypotheses) {
    const double conf = std::clamp(h.confidence, 0.0, 1.0);
    visualization_msgs::Marker arrow;
    arrow.header = header;
    arrow.ns = "hypotheses";
    arrow.id = id++;
    arrow.type = visualization_msgs::Marker::ARROW;
    arrow.action = visualization_msgs::Marker::ADD;
    arrow.pose = poseToRos(map.toSourceFrame(h.pose));
    arrow.scale.x = kMarkerMaxLengthM * (0.3 + 0.7 * conf);
    arrow.scale.y = arrow.scale.z = 0.1;
    // Green for confident, red for doubtful.
    arrow.color.r = static_cast<float>(1.0 - conf);
    arrow.color.g = static_cast<float>(conf);
    arrow.color.a = 1.0f;
    out.markers.push_back(arrow);
    visualization_msgs::Marker text = arrow;
    text.ns = "confidence";
    text.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    text.scale.z = 0.3;
    text.pose.position.z = 0.5;
    std::ostringstream s;
    s.precision(2);
    s << std::fixed << conf << " (fit " << h.fit_fraction << ")";
    text.text = s.str();
    out.markers.push_back(text);
  }
  return out;
}

}  // namespace krp::ros1
