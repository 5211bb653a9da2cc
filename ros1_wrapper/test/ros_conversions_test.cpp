// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <limits>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "ros_conversions.h"
#include "support/test_maps.h"

namespace krp::ros1 {
namespace {

sensor_msgs::LaserScan fullCircleScan(size_t n, float range) {
  sensor_msgs::LaserScan m;
  m.header.frame_id = "laser";
  m.angle_min = static_cast<float>(-M_PI);
  m.angle_increment = static_cast<float>(2 * M_PI / n);
  m.angle_max = m.angle_min + m.angle_increment * static_cast<float>(n - 1);
  m.range_min = 0.05f;
  m.range_max = 12.0f;
  m.ranges.assign(n, range);
  return m;
}

/// The scan's returns in the robot frame as MRPT itself projects them; the one farthest from
/// the sensor (tests mark one beam with a longer range).
mrpt::math::TPoint2D farthestReturn(const mrpt::obs::CObservation2DRangeScan& s) {
  mrpt::maps::CSimplePointsMap pts;
  pts.loadFromRangeScan(s);
  mrpt::math::TPoint2D best;
  double best_d = -1;
  for (size_t i = 0; i < pts.size(); ++i) {
    float x, y;
    pts.getPoint(i, x, y);
    const double d = std::hypot(x - s.sensorPose.x(), y - s.sensorPose.y());
    if (d > best_d) best_d = d, best = mrpt::math::TPoint2D(x, y);
  }
  return best;
}

TEST(RosConversions, ScanBeamsPointWhereTheRosAnglesSay) {
  auto msg = fullCircleScan(360, 2.0f);
  // An asymmetric ROS scan: beam 0 at -pi. Mark beam 90 (angle -pi/2) with a distinct range.
  msg.ranges[90] = 3.0f;
  const mrpt::poses::CPose3D laser_in_base(0.2, 0.0, 0.1, 0.0, 0, 0);
  const auto scan = scanFromRos(msg, laser_in_base);
  ASSERT_EQ(scan->getScanSize(), 360u);
  const auto p = farthestReturn(*scan);
  EXPECT_NEAR(p.x, 0.2, 1e-3);  // straight to the robot's right of the sensor
  EXPECT_NEAR(p.y, -3.0, 1e-3);
}

TEST(RosConversions, ReversedScansKeepTheirGeometry) {
  auto msg = fullCircleScan(100, 2.0f);
  std::swap(msg.angle_min, msg.angle_max);
  msg.angle_increment = -msg.angle_increment;
  msg.ranges[0] = 4.0f;  // at angle_min, now +pi - inc
  const auto scan = scanFromRos(msg, mrpt::poses::CPose3D());
  const auto p = farthestReturn(*scan);
  const double a = msg.angle_min;
  EXPECT_NEAR(p.x, 4.0 * std::cos(a), 1e-3);
  EXPECT_NEAR(p.y, 4.0 * std::sin(a), 1e-3);
}

TEST(RosConversions, MrptScansRoundTripThroughLaserScan) {
  for (const char* profile : {"omni_12m", "safety_270"}) {
    Rng rng(2);
    const auto room = krp::test::asymmetricRoom();
    auto original = ScanSimulator(lidarProfileByName(profile)).simulate(room, mrpt::poses::CPose2D(5.5, 2.1, 0.4), rng);
    for (bool right_to_left : {true, false}) {
      original->rightToLeft = right_to_left;
      const auto msg = scanToRos(*original, ros::Time(5.0), "laser");
      const auto back = scanFromRos(msg, mrpt::poses::CPose3D(original->sensorPose));
      mrpt::maps::CSimplePointsMap a, b;
      // Every return, not MRPT's default thinning to 2 cm apart.
      a.insertionOptions.minDistBetweenLaserPoints = b.insertionOptions.minDistBetweenLaserPoints = 0;
      a.loadFromRangeScan(*original);
      b.loadFromRangeScan(*back);
      ASSERT_EQ(a.size(), b.size()) << profile << " right_to_left " << right_to_left;
      for (size_t i = 0; i < a.size(); i += 37) {
        float ax, ay, bx, by;
        a.getPoint(i, ax, ay);
        b.getPoint(i, bx, by);
        EXPECT_NEAR(ax, bx, 1e-3) << profile << " beam " << i;
        EXPECT_NEAR(ay, by, 1e-3) << profile << " beam " << i;
      }
    }
  }
}

TEST(RosConversions, BadReadingsBecomeNoReturns) {
  auto msg = fullCircleScan(100, 2.0f);
  msg.ranges[0] = std::numeric_limits<float>::quiet_NaN();
  msg.ranges[1] = std::numeric_limits<float>::infinity();
  msg.ranges[2] = -1.0f;
  msg.ranges[3] = 50.0f;   // beyond range_max
  msg.ranges[4] = 0.01f;   // below range_min
  const auto scan = scanFromRos(msg, mrpt::poses::CPose3D());
  for (size_t i = 0; i < 5; ++i) EXPECT_FALSE(scan->getScanRangeValidity(i)) << i;
  EXPECT_TRUE(scan->getScanRangeValidity(5));
}

TEST(RosConversions, UnusableScansAreRejectedWithTheReason) {
  auto all_nan = fullCircleScan(100, std::numeric_limits<float>::quiet_NaN());
  auto wrong_count = fullCircleScan(100, 2.0f);
  wrong_count.ranges.resize(80);
  auto bad_angles = fullCircleScan(100, 2.0f);
  bad_angles.angle_increment = 0.0f;
  auto empty = fullCircleScan(100, 2.0f);
  empty.ranges.clear();
  const std::pair<sensor_msgs::LaserScan, std::string> cases[] = {
      {all_nan, "usable returns"}, {wrong_count, "80 ranges"}, {bad_angles, "increment"}, {empty, "fewer than 2"}};
  for (const auto& [msg, expected] : cases) {
    try {
      scanFromRos(msg, mrpt::poses::CPose3D());
      ADD_FAILURE() << "accepted; expected: " << expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("laser"), std::string::npos) << "names the frame: " << e.what();
    }
  }
}

nav_msgs::OccupancyGrid gridMsg(unsigned w, unsigned h) {
  nav_msgs::OccupancyGrid m;
  m.header.frame_id = "map";
  m.info.width = w;
  m.info.height = h;
  m.info.resolution = 0.1f;
  m.info.origin.position.x = -2.0;
  m.info.origin.position.y = 1.0;
  m.info.origin.orientation.w = 1.0;
  m.data.assign(static_cast<size_t>(w) * h, 0);
  return m;
}

TEST(RosConversions, OccupancyGridCellsAndOrigin) {
  auto msg = gridMsg(20, 10);
  msg.data[3 * 20 + 5] = 100;  // row 3 (y), column 5 (x): occupied
  msg.data[0] = -1;            // unknown
  const auto map = occupancyMapFromRos(msg);
  const auto& g = *map.grid;
  EXPECT_EQ(g.getSizeX(), 20u);
  EXPECT_EQ(g.getSizeY(), 10u);
  EXPECT_NEAR(g.getXMin(), -2.0, 1e-6);
  EXPECT_NEAR(g.getYMin(), 1.0, 1e-6);
  // getCell is p(free).
  EXPECT_LT(g.getCell(5, 3), 0.1);
  EXPECT_GT(g.getCell(6, 3), 0.9);
  EXPECT_NEAR(g.getCell(0, 0), 0.5, 0.05);
  EXPECT_LT(g.getPos(-2.0 + 0.55, 1.0 + 0.35), 0.1);  // the same cell by coordinates
}

TEST(RosConversions, BadOccupancyGridsAreRejected) {
  auto empty = gridMsg(0, 0);
  auto short_data = gridMsg(10, 10);
  short_data.data.resize(50);
  auto bad_res = gridMsg(10, 10);
  bad_res.info.resolution = std::numeric_limits<float>::quiet_NaN();
  auto nan_origin = gridMsg(10, 10);
  nan_origin.info.origin.position.x = std::numeric_limits<double>::quiet_NaN();
  auto all_occupied = gridMsg(10, 10);
  all_occupied.data.assign(100, 100);
  // Found by ros_messages_fuzzer: MRPT keeps extents in float and asserted on this one.
  auto far_origin = gridMsg(10, 10);
  far_origin.info.origin.position.x = 3.0e38;
  for (const auto& m : {empty, short_data, bad_res, nan_origin, all_occupied, far_origin})
    EXPECT_THROW(occupancyMapFromRos(m), InputError);
}

TEST(RosConversions, YawedMapPosesComeOutInTheMapFrame) {
  auto msg = gridMsg(100, 100);
  const double yaw = M_PI / 2;
  msg.info.origin.orientation.z = std::sin(yaw / 2);
  msg.info.origin.orientation.w = std::cos(yaw / 2);
  const auto map = occupancyMapFromRos(msg);
  PoseHypothesis h;
  h.pose = mrpt::math::TPose2D(-2.0 + 1.0, 1.0, 0.0);  // 1 m along the grid's x from its origin
  h.cov.setZero();
  h.cov(0, 0) = 0.04;  // x variance in the grid frame -> y variance in the map frame
  h.cov(1, 1) = 0.01;
  h.cov(2, 2) = 0.003;
  std_msgs::Header header;
  const auto m = initialPoseMsg(h, map, header);
  EXPECT_NEAR(m.pose.pose.position.x, -2.0, 1e-9);
  EXPECT_NEAR(m.pose.pose.position.y, 2.0, 1e-9);
  EXPECT_NEAR(pose2DFromRos(m.pose.pose).phi, yaw, 1e-9);
  EXPECT_NEAR(m.pose.covariance[0], 0.01, 1e-12);
  EXPECT_NEAR(m.pose.covariance[7], 0.04, 1e-12);
  EXPECT_NEAR(m.pose.covariance[35], 0.003, 1e-12);  // yaw variance where AMCL reads it
}

TEST(RosConversions, CovarianceRoundTripsAndBadOnesGetDefaults) {
  mrpt::math::CMatrixDouble33 c;
  c.setZero();
  c(0, 0) = 0.04, c(1, 1) = 0.09, c(2, 2) = 0.01, c(0, 1) = c(1, 0) = 0.01;
  const auto back = covarianceFromRos(covarianceToRos(c), 0.0);
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(back(r, k), c(r, k), 1e-12);
  boost::array<double, 36> zero{};
  const auto d = covarianceFromRos(zero, 0.0);
  EXPECT_NEAR(d(0, 0), 0.25, 1e-12);  // AMCL's initial_cov_xx
  EXPECT_NEAR(d(2, 2), std::pow(M_PI / 12, 2), 1e-12);
  boost::array<double, 36> nan{};
  nan[0] = std::numeric_limits<double>::quiet_NaN();
  nan[7] = 0.09;
  nan[35] = 0.01;
  const auto n = covarianceFromRos(nan, 0.0);
  EXPECT_NEAR(n(0, 0), 0.25, 1e-12);
  EXPECT_NEAR(n(1, 1), 0.09, 1e-12);
}

TEST(RosConversions, HypothesesForRviz) {
  const auto map = occupancyMapFromRos(gridMsg(50, 50));
  Ranking r;
  for (double c : {0.9, 0.1}) {
    PoseHypothesis h;
    h.pose = mrpt::math::TPose2D(0.0, 2.0, c);
    h.confidence = c;
    r.hypotheses.push_back(h);
  }
  std_msgs::Header header;
  header.frame_id = "map";
  EXPECT_EQ(hypothesesPoseArray(r, map, header).poses.size(), 2u);
  const auto markers = hypothesesMarkers(r, map, header);
  ASSERT_EQ(markers.markers.size(), 5u);  // DELETEALL + (arrow, text) per hypothesis
  EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETEALL);
  EXPECT_GT(markers.markers[1].color.g, markers.markers[3].color.g);  // the confident one is greener
}

}  // namespace
}  // namespace krp::ros1
