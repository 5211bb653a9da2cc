// SPDX-License-Identifier: BSD-3-Clause
#include <ros/ros.h>

#include "relocalizer_node.h"

namespace {
// Scans, the map, services and AMCL's pose each get a thread, so that `~relocalize` waiting
// for its answer never holds up the scan callback.
constexpr int kSpinnerThreads = 4;
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "krp_relocalizer");
  ros::NodeHandle nh, private_nh("~");
  try {
    krp::ros1::RelocalizerNode node(nh, private_nh);
    ros::AsyncSpinner spinner(kSpinnerThreads);
    spinner.start();
    ros::waitForShutdown();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("krp_relocalizer: " << e.what());
    return 1;
  }
  return 0;
}
