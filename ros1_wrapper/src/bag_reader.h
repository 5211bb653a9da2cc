// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/sim/rawlog_io.h"
#include "ros_conversions.h"

namespace krp::ros1 {

struct BagReadParams {
  std::string scan_topic = "/scan";
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  ScanCheck scan_check;
  OdometryModelParams odometry;  ///< noise model attached to each odometry increment
};

struct BagSteps {
  std::vector<RawlogStep> steps;  ///< one per usable scan: odometry since the previous one + the scan
  int scans_seen = 0;
  int skipped_no_transform = 0;   ///< no odom -> base or base -> laser at the scan's time
  int skipped_bad_scan = 0;       ///< rejected by scanFromRos
  std::string first_problem;      ///< the first skip's reason, for the user
};

/// Reads LaserScans and tf (/tf, /tf_static) from a ROS 1 bag into the same steps a rawlog
/// gives, so every tool that runs on a rawlog runs on a bag. InputError for a missing,
/// unreadable or truncated bag, a bag without the scan topic, or one where no scan could be used.
BagSteps readBag(const std::string& path, const BagReadParams& params = {});

}  // namespace krp::ros1
