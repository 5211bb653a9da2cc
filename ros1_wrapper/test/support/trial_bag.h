// SPDX-License-Identifier: BSD-3-Clause
// Test support: a simulated trial written as a ROS 1 bag (/scan, /tf, /tf_static), as a robot
// would record it.
#pragma once

#include <rosbag/stream.h>

#include <string>

#include "mrpt_krp_plugin/sim/trial.h"

namespace krp::ros1::test {

/// Scans on /scan in frame "laser", odom -> base_link on /tf at each scan's time (starting at
/// `odom_origin`), base_link -> laser on /tf_static. Scan i is stamped 100 + 0.1 i s. Chunks are
/// written with `compression` (rosbag's: Uncompressed, BZ2 or LZ4).
void writeTrialBag(const Trial& trial, const std::string& path,
                   const mrpt::math::TPose2D& odom_origin = mrpt::math::TPose2D(1.0, -2.0, 0.5),
                   rosbag::compression::CompressionType compression = rosbag::compression::Uncompressed);

}  // namespace krp::ros1::test
