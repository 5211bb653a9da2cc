// SPDX-License-Identifier: BSD-3-Clause
// The "robot" side of the node's integration tests: replays a simulated kidnap from a sim world
// (map, scans, tf) to a running krp_relocalizer_node and checks what it publishes. Run by
// run_node_test.sh, which starts a roscore on loopback and the node.
#include <gtest/gtest.h>

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>

#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "ros_conversions.h"

namespace krp::ros1 {
namespace {

constexpr double kMaxErrorM = 0.3;
constexpr double kMaxErrorDeg = 5.0;
constexpr double kScanPeriodS = 0.1;
// How long a status the node has published may take to reach the test's subscriber.
constexpr double kStatusWaitS = 5.0;
// Longer than the node's default max_scan_age_s (1 s), so that the last scan it could use is stale.
constexpr double kTransformGapS = 2.0;
const char* kWorld = KRP_SOURCE_DIR "/sim_worlds/office_two_zone/office_two_zone.world.yaml";

nav_msgs::OccupancyGrid toRos(const mrpt::maps::COccupancyGridMap2D& g) {
  nav_msgs::OccupancyGrid m;
  m.header.frame_id = "map";
  m.info.width = g.getSizeX();
  m.info.height = g.getSizeY();
  m.info.resolution = g.getResolution();
  m.info.origin.position.x = g.getXMin();
  m.info.origin.position.y = g.getYMin();
  m.info.origin.orientation.w = 1.0;
  for (unsigned y = 0; y < g.getSizeY(); ++y)
    for (unsigned x = 0; x < g.getSizeX(); ++x)
      m.data.push_back(static_cast<int8_t>(std::lround(100.0 * (1.0 - g.getCell(x, y)))));
  return m;
}

/// The robot: publishes tf (odom -> base_link, base_link -> laser) and scans, and listens to
/// what the node says.
class Robot {
 public:
  Robot() : listener_(buffer_) {
    scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 5);
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    pose_sub_ = nh_.subscribe("initialpose", 5, &Robot::onPose, this);
    status_sub_ = nh_.subscribe("krp_relocalizer/status", 50, &Robot::onStatus, this);
    static_broadcaster_.sendTransform(transformToRos({0, 0, 0}, "base_link", "laser", ros::Time::now()));
  }

  // The spinner threads may be inside a callback: unsubscribe (which waits for it) before the
  // members the callbacks use are destroyed.
  ~Robot() {
    pose_sub_.shutdown();
    status_sub_.shutdown();
  }

  /// One scan at `odom`, with its transform, stamped now.
  void publish(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& odom,
               const std::string& frame = "laser") {
    const ros::Time stamp = ros::Time::now();
    broadcaster_.sendTransform(transformToRos(odom, "odom", "base_link", stamp));
    scan_pub_.publish(scanToRos(scan, stamp, frame));
  }

  /// One scan stamped now, without its odom -> base_link transform.
  void publishScanOnly(const mrpt::obs::CObservation2DRangeScan& scan) {
    scan_pub_.publish(scanToRos(scan, ros::Time::now(), "laser"));
  }

  /// Publishes the same scan every kScanPeriodS until `done` or the timeout; true if done.
  bool publishUntil(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& odom, double timeout_s,
                    const std::function<bool()>& done) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout_s);
    while (ros::WallTime::now() < end) {
      publish(scan, odom);
      if (done()) return true;
      ros::WallDuration(kScanPeriodS).sleep();
    }
    return done();
  }

  std::optional<geometry_msgs::PoseWithCovarianceStamped> lastPose() {
    std::lock_guard<std::mutex> lock(mutex_);
    return pose_;
  }
  void clearPose() {
    std::lock_guard<std::mutex> lock(mutex_);
    pose_.reset();
  }
  bool statusContains(const std::string& text) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& s : statuses_)
      if (s.find(text) != std::string::npos) return true;
    return false;
  }
  std::string statuses() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::string all;
    for (const auto& s : statuses_) all += s + "\n";
    return all;
  }

  ros::NodeHandle nh_;
  ros::Publisher scan_pub_, map_pub_;
  tf2_ros::Buffer buffer_;

 private:
  void onPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    pose_ = *m;
  }
  void onStatus(const std_msgs::String::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    statuses_.push_back(m->data);
  }

  ros::Subscriber pose_sub_, status_sub_;
  tf2_ros::TransformListener listener_;
  tf2_ros::TransformBroadcaster broadcaster_;
  tf2_ros::StaticTransformBroadcaster static_broadcaster_;
  std::mutex mutex_;
  std::optional<geometry_msgs::PoseWithCovarianceStamped> pose_;
  std::vector<std::string> statuses_;
};

void expectNear(const mrpt::math::TPose2D& got, const mrpt::math::TPose2D& truth, const std::string& what) {
  EXPECT_LT(std::hypot(got.x - truth.x, got.y - truth.y), kMaxErrorM)
      << what << ": got " << got.asString() << ", truth " << truth.asString();
  EXPECT_LT(std::abs(mrpt::math::wrapToPi(got.phi - truth.phi)) * 180.0 / M_PI, kMaxErrorDeg)
      << what << ": got " << got.asString() << ", truth " << truth.asString();
}

struct Kidnaps {
  World world = readWorld(kWorld);
  OccupancyMap map = loadOccupancyMap(world.map_path);
  Trial first = generateTrial(*map.grid, world.lidar(world.default_lidar_profile), TrialParams{}, 11);
  Trial second = generateTrial(*map.grid, world.lidar(world.default_lidar_profile), TrialParams{}, 12);
};

bool waitForService(const std::string& name) { return ros::service::waitForService(name, ros::Duration(30.0)); }

// Mode `relocalize` (beside AMCL): the node is started with ~map_file and the global matcher.
TEST(RosNodeRelocalize, GlobalLocalizationPublishesTheKidnappedPose) {
  Kidnaps k;
  Robot robot;
  ASSERT_TRUE(waitForService("global_localization"));
  // The odometry frame is wherever the robot was switched on: not the map's.
  const mrpt::math::TPose2D odom(3.0, -1.0, 0.4);
  // Started with relocalize_on_startup: false, so nothing comes until the service is called.
  robot.publishUntil(*k.first.scans[0], odom, 1.0, [] { return false; });
  EXPECT_FALSE(robot.lastPose().has_value()) << "published before being asked";
  std_srvs::Empty empty;
  ASSERT_TRUE(ros::service::call("global_localization", empty));
  ASSERT_TRUE(robot.publishUntil(*k.first.scans[0], odom, 60.0, [&] { return robot.lastPose().has_value(); }))
      << robot.statuses();
  const auto pose = *robot.lastPose();
  EXPECT_EQ(pose.header.frame_id, "map");
  expectNear(pose2DFromRos(pose.pose.pose), k.first.truth[0], "initialpose");
  EXPECT_GT(pose.pose.covariance[35], 0.0) << "yaw variance at index 35";

  // Carried elsewhere: ~relocalize answers with the new pose.
  robot.clearPose();
  robot.publishUntil(*k.second.scans[0], odom, 0.5, [] { return false; });
  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("krp_relocalizer/relocalize", trigger));
  EXPECT_TRUE(trigger.response.success) << trigger.response.message;
  ASSERT_TRUE(robot.publishUntil(*k.second.scans[0], odom, 10.0, [&] { return robot.lastPose().has_value(); }));
  expectNear(pose2DFromRos(robot.lastPose()->pose.pose), k.second.truth[0], "initialpose after the second kidnap");
}

TEST(RosNodeRelocalize, BadScansAndMissingTransformsAreReportedAndTheNodeGoesOn) {
  Kidnaps k;
  Robot robot;
  ASSERT_TRUE(waitForService("krp_relocalizer/relocalize"));
  const mrpt::math::TPose2D odom(0, 0, 0);
  auto nan_scan = *k.first.scans[0];
  for (size_t i = 0; i < nan_scan.getScanSize(); ++i) nan_scan.setScanRangeValidity(i, false);
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(10.0);
  while (ros::WallTime::now() < end && !(robot.statusContains("usable returns") && robot.statusContains("no transform"))) {
    robot.publish(nan_scan, odom);
    robot.publish(*k.first.scans[0], odom, "a_frame_nobody_publishes");
    ros::WallDuration(kScanPeriodS).sleep();
  }
  EXPECT_TRUE(robot.statusContains("usable returns")) << robot.statuses();
  EXPECT_TRUE(robot.statusContains("no transform")) << robot.statuses();
  // Still alive and answering: with no usable scan it says so instead of guessing.
  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("krp_relocalizer/relocalize", trigger));
  EXPECT_FALSE(trigger.response.success);
  EXPECT_NE(trigger.response.message.find("not localized"), std::string::npos) << trigger.response.message;
  // And a good scan afterwards still works.
  robot.publishUntil(*k.first.scans[0], odom, 0.5, [] { return false; });
  ASSERT_TRUE(ros::service::call("krp_relocalizer/relocalize", trigger));
  EXPECT_TRUE(trigger.response.success) << trigger.response.message;
}

// The odom -> base_link transform stops (an odometry driver restarting) while scans keep coming,
// then comes back: meanwhile the node ignores the scans, says why, and refuses to relocalize from
// the stale last good one; afterwards it relocalizes again.
TEST(RosNodeRelocalize, TransformsGoingMissingAndComingBack) {
  Kidnaps k;
  Robot robot;
  ASSERT_TRUE(waitForService("krp_relocalizer/relocalize"));
  const mrpt::math::TPose2D odom(0, 0, 0);
  robot.publishUntil(*k.first.scans[0], odom, 0.5, [] { return false; });
  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("krp_relocalizer/relocalize", trigger));
  EXPECT_TRUE(trigger.response.success) << "before the gap: " << trigger.response.message;

  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(kTransformGapS);
  while (ros::WallTime::now() < end) {
    robot.publishScanOnly(*k.first.scans[0]);
    ros::WallDuration(kScanPeriodS).sleep();
  }
  EXPECT_TRUE(robot.statusContains("no transform")) << robot.statuses();
  ASSERT_TRUE(ros::service::call("krp_relocalizer/relocalize", trigger));
  EXPECT_FALSE(trigger.response.success) << "relocalized from a stale scan: " << trigger.response.message;
  EXPECT_NE(trigger.response.message.find("old"), std::string::npos) << trigger.response.message;

  robot.publishUntil(*k.first.scans[0], odom, 0.5, [] { return false; });
  robot.clearPose();
  ASSERT_TRUE(ros::service::call("krp_relocalizer/relocalize", trigger));
  EXPECT_TRUE(trigger.response.success) << "after the gap: " << trigger.response.message;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
  while (!robot.lastPose() && ros::WallTime::now() < deadline) ros::WallDuration(kScanPeriodS).sleep();
  ASSERT_TRUE(robot.lastPose().has_value()) << "no initialpose after the gap";
  expectNear(pose2DFromRos(robot.lastPose()->pose.pose), k.first.truth[0], "relocalized after the gap");
}

// Beside AMCL with relocalize_on_kidnap: AMCL (played by the test) keeps reporting the old pose
// while the robot has been carried off; the scans stop fitting there and the node relocalizes.
TEST(RosNodeRelocalize, KidnapBesideAmclIsDetectedAndRelocalized) {
  Kidnaps k;
  Robot robot;
  ros::Publisher amcl = robot.nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 5);
  ASSERT_TRUE(waitForService("global_localization"));
  const mrpt::math::TPose2D odom(0, 0, 0);
  geometry_msgs::PoseWithCovarianceStamped amcl_pose;
  amcl_pose.header.frame_id = "map";
  amcl_pose.pose.pose = poseToRos(k.first.truth[0]);
  auto publishBoth = [&](const mrpt::obs::CObservation2DRangeScan& scan) {
    amcl_pose.header.stamp = ros::Time::now();
    amcl.publish(amcl_pose);
    robot.publish(scan, odom);
  };
  // Tracking well: the scans fit at AMCL's pose, nothing is published.
  for (int i = 0; i < 15; ++i) {
    publishBoth(*k.first.scans[0]);
    ros::WallDuration(kScanPeriodS).sleep();
  }
  EXPECT_FALSE(robot.lastPose().has_value()) << robot.statuses();
  // Carried off: AMCL still believes the old pose.
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::WallTime::now() < end && !robot.lastPose()) {
    publishBoth(*k.second.scans[0]);
    ros::WallDuration(kScanPeriodS).sleep();
  }
  ASSERT_TRUE(robot.lastPose().has_value()) << robot.statuses();
  EXPECT_TRUE(robot.statusContains("kidnap suspected")) << robot.statuses();
  expectNear(pose2DFromRos(robot.lastPose()->pose.pose), k.second.truth[0], "initialpose after the kidnap");
}

// backend `learned` with the shipped office models: the node loads them and answers with the
// pipeline's own verdict (the models are weak, so "not localized" is an honest answer; what must
// not happen is a crash, a hang or an answer that is not from the pipeline).
TEST(RosNodeLearned, AnswersWithThePipelinesVerdict) {
  Kidnaps k;
  Robot robot;
  ASSERT_TRUE(waitForService("krp_relocalizer/relocalize"));
  const mrpt::math::TPose2D odom(0, 0, 0);
  robot.publishUntil(*k.first.scans[0], odom, 1.0, [] { return false; });
  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("krp_relocalizer/relocalize", trigger));
  const std::string& m = trigger.response.message;
  if (trigger.response.success) {
    EXPECT_NE(m.find("confidence="), std::string::npos) << m;
  } else {
    EXPECT_EQ(m.find("no usable scan"), std::string::npos) << m;
    EXPECT_EQ(m.find("no map"), std::string::npos) << m;
    EXPECT_EQ(m.find("trigger_timeout"), std::string::npos) << m;
    EXPECT_NE(m.find("not localized: "), std::string::npos) << m;
  }
  // The start-up status names the backend too, but `~status` is latched, so a subscriber that
  // comes late sees only the newest message: the answer's own status is the one to wait for.
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(kStatusWaitS);
  while (ros::WallTime::now() < end && !robot.statusContains("backend learned")) ros::WallDuration(kScanPeriodS).sleep();
  EXPECT_TRUE(robot.statusContains("backend learned")) << robot.statuses();
}

// A model file replaced on disk while the node runs (a half-copied update): the node keeps the
// models it loaded; `~reload` refuses the broken file and keeps them too, and takes the file once
// it is good again. The node runs on a copy of the shipped models in KRP_TEST_MODELS_DIR.
TEST(RosNodeLearned, ReplacedModelFileIsTakenOnlyOnReloadAndOnlyIfItLoads) {
  const char* dir = std::getenv("KRP_TEST_MODELS_DIR");
  ASSERT_NE(dir, nullptr) << "KRP_TEST_MODELS_DIR is not set";
  const std::string copy = std::string(dir) + "/keypoints.onnx";
  const std::string original = std::string(KRP_SOURCE_DIR) + "/models/office_two_zone/keypoints.onnx";
  Kidnaps k;
  Robot robot;
  ASSERT_TRUE(waitForService("krp_relocalizer/reload"));
  const mrpt::math::TPose2D odom(0, 0, 0);
  auto relocalize = [&] {
    robot.publishUntil(*k.first.scans[0], odom, 0.5, [] { return false; });
    std_srvs::Trigger t;
    EXPECT_TRUE(ros::service::call("krp_relocalizer/relocalize", t));
    return t.response;
  };
  const auto before = relocalize();
  std::ofstream(copy, std::ios::trunc) << "half a model";

  const auto while_broken = relocalize();
  EXPECT_EQ(while_broken.success, before.success) << while_broken.message;
  EXPECT_EQ(while_broken.message.find("failed"), std::string::npos) << while_broken.message;
  std_srvs::Trigger reload;
  ASSERT_TRUE(ros::service::call("krp_relocalizer/reload", reload));
  EXPECT_FALSE(reload.response.success);
  EXPECT_NE(reload.response.message.find("not reloaded, keeping the loaded backend"), std::string::npos)
      << reload.response.message;
  EXPECT_NE(reload.response.message.find("keypoints.onnx"), std::string::npos) << reload.response.message;
  const auto after_refused = relocalize();
  EXPECT_EQ(after_refused.success, before.success) << after_refused.message;
  EXPECT_EQ(after_refused.message.find("failed"), std::string::npos) << after_refused.message;

  std::filesystem::copy_file(original, copy, std::filesystem::copy_options::overwrite_existing);
  ASSERT_TRUE(ros::service::call("krp_relocalizer/reload", reload));
  EXPECT_TRUE(reload.response.success) << reload.response.message;
  EXPECT_EQ(relocalize().success, before.success);
}

// The map comes on a topic and is re-published mid-run: a good one is re-read, a broken one is
// rejected and the previous one kept; either way the node goes on relocalizing.
TEST(RosNodeRelocalize, RepublishedMapsAreRereadAndBrokenOnesRejected) {
  Kidnaps k;
  Robot robot;
  auto good = toRos(*k.map.grid);
  robot.map_pub_.publish(good);
  ASSERT_TRUE(waitForService("krp_relocalizer/relocalize"));
  const mrpt::math::TPose2D odom(0, 0, 0);
  ASSERT_TRUE(robot.publishUntil(*k.first.scans[0], odom, 30.0, [&] { return robot.statusContains("map in use"); }))
      << robot.statuses();
  auto broken = good;
  broken.data.resize(broken.data.size() / 2);
  robot.map_pub_.publish(broken);
  ASSERT_TRUE(robot.publishUntil(*k.first.scans[0], odom, 10.0, [&] {
    return robot.statusContains("map rejected, keeping the previous one");
  })) << robot.statuses();
  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("krp_relocalizer/relocalize", trigger));
  EXPECT_TRUE(trigger.response.success) << trigger.response.message;
  // A good map again (re-stamped): re-read, and relocalization still works on it.
  good.header.stamp = ros::Time::now();
  robot.map_pub_.publish(good);
  ros::WallDuration(2.0).sleep();
  robot.publishUntil(*k.second.scans[0], odom, 1.0, [] { return false; });
  ASSERT_TRUE(ros::service::call("krp_relocalizer/relocalize", trigger));
  EXPECT_TRUE(trigger.response.success) << trigger.response.message;
  int maps_in_use = 0;
  for (std::string all = robot.statuses(); all.find("map in use") != std::string::npos;
       all = all.substr(all.find("map in use") + 1))
    ++maps_in_use;
  EXPECT_EQ(maps_in_use, 2) << robot.statuses();
}

// Mode `track`: the node gets the map on `map`, seeds its own filter from the first scan and
// publishes map -> odom.
TEST(RosNodeTrack, MapToOdomConverges) {
  Kidnaps k;
  Robot robot;
  robot.map_pub_.publish(toRos(*k.map.grid));
  ASSERT_TRUE(waitForService("global_localization"));
  mrpt::poses::CPose2D odom(-4.0, 2.0, -1.0);
  const Trial& t = k.first;
  for (size_t i = 0; i < t.scans.size(); ++i) {
    odom = odom + t.odometry[i];
    // The first scan waits for the node to seed (the map arrives on a topic first).
    if (i == 0) robot.publishUntil(*t.scans[0], odom.asTPose(), 30.0, [&] {
      return robot.statusContains("filter seeded");
    });
    else robot.publish(*t.scans[i], odom.asTPose());
    ros::WallDuration(kScanPeriodS).sleep();
  }
  ASSERT_TRUE(robot.statusContains("filter seeded")) << robot.statuses();
  geometry_msgs::TransformStamped map_to_base;
  try {
    map_to_base = robot.buffer_.lookupTransform("map", "base_link", ros::Time(0), ros::Duration(5.0));
  } catch (const tf2::TransformException& e) {
    FAIL() << "no map -> base_link: " << e.what() << "\n" << robot.statuses();
  }
  expectNear(pose2DFromRos(map_to_base.transform), t.truth.back(), "map -> base_link at the end of the trial");

  // A user gives a pose on `initialpose` (RViz's 2D Pose Estimate) after carrying the robot:
  // the filter re-seeds there, as AMCL's does.
  const Trial& moved = k.second;
  geometry_msgs::PoseWithCovarianceStamped given;
  given.header.frame_id = "map";
  given.header.stamp = ros::Time::now();
  given.pose.pose = poseToRos(mrpt::math::TPose2D(moved.truth[0].x + 0.2, moved.truth[0].y - 0.2, moved.truth[0].phi));
  given.pose.covariance[0] = given.pose.covariance[7] = 0.25;
  given.pose.covariance[35] = 0.07;
  ros::Publisher initialpose = robot.nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("initialpose", 1, true);
  initialpose.publish(given);
  ASSERT_TRUE(robot.publishUntil(*moved.scans[0], odom.asTPose(), 10.0, [&] {
    return robot.statusContains("initialpose received");
  })) << robot.statuses();
  for (size_t i = 1; i < moved.scans.size(); ++i) {
    odom = odom + moved.odometry[i];
    robot.publish(*moved.scans[i], odom.asTPose());
    ros::WallDuration(kScanPeriodS).sleep();
  }
  ros::WallDuration(1.0).sleep();
  map_to_base = robot.buffer_.lookupTransform("map", "base_link", ros::Time(0), ros::Duration(5.0));
  expectNear(pose2DFromRos(map_to_base.transform), moved.truth.back(), "map -> base_link after initialpose");
}

}  // namespace
}  // namespace krp::ros1

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "krp_node_integration_test", ros::init_options::AnonymousName);
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  ros::shutdown();
  return rc;
}
