// SPDX-License-Identifier: BSD-3-Clause
#include "support/trial_bag.h"

#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include "ros_conversions.h"

namespace krp::ros1::test {


void writeTrialBag(const Trial& trial, const std::string& path, const mrpt::math::TPose2D& odom_origin,
                   rosbag::compression::CompressionType compression) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  bag.setCompression(compression);
  const ros::Time start(100.0);
  tf2_msgs::TFMessage statics;
  const auto& mount = trial.scans.front()->sensorPose;
  statics.transforms.push_back(
      transformToRos(mrpt::math::TPose2D(mount.x(), mount.y(), mount.yaw()), "base_link", "laser", start));
  bag.write("/tf_static", start, statics);
  mrpt::poses::CPose2D odom(odom_origin);
  for (size_t i = 0; i < trial.scans.size(); ++i) {
    const ros::Time stamp = start + ros::Duration(0.1 * static_cast<double>(i));
    odom = odom + trial.odometry[i];
    tf2_msgs::TFMessage tf;
    tf.transforms.push_back(transformToRos(odom.asTPose(), "odom", "base_link", stamp));
    bag.write("/tf", stamp, tf);
    const auto m = scanToRos(*trial.scans[i], stamp, "laser");
    bag.write("/scan", stamp, m);
  }
  bag.close();
}

}  // namespace krp::ros1::test
