// SPDX-License-Identifier: BSD-3-Clause
#include "message_bounds.h"

#include <gtest/gtest.h>
#include <ros/serialization.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <cstring>
#include <vector>

namespace krp::ros1 {
namespace {

template <typename M>
std::vector<uint8_t> serialized(const M& msg) {
  std::vector<uint8_t> bytes(ros::serialization::serializationLength(msg));
  ros::serialization::OStream out(bytes.data(), static_cast<uint32_t>(bytes.size()));
  ros::serialization::serialize(out, msg);
  return bytes;
}

void putCount(std::vector<uint8_t>& bytes, size_t at, uint32_t count) { std::memcpy(bytes.data() + at, &count, sizeof(count)); }

sensor_msgs::LaserScan scan() {
  sensor_msgs::LaserScan s;
  s.header.frame_id = "laser";
  s.ranges.assign(360, 2.0f);
  s.intensities.assign(360, 1.0f);
  return s;
}

TEST(MessageBounds, WellFormedMessagesPass) {
  const auto bytes = serialized(scan());
  EXPECT_EQ(laserScanBoundsProblem(bytes.data(), bytes.size()), "");
  tf2_msgs::TFMessage tf;
  tf.transforms.resize(3);
  tf.transforms[1].child_frame_id = "base_link";
  const auto tf_bytes = serialized(tf);
  EXPECT_EQ(tfMessageBoundsProblem(tf_bytes.data(), tf_bytes.size()), "");
}

TEST(MessageBounds, AHugeRangesCountIsNamedNotAllocated) {
  auto bytes = serialized(scan());
  // header: seq, stamp (2), frame_id "laser" (count + 5), then 7 floats: the ranges count follows.
  const size_t ranges_at = 3 * 4 + 4 + 5 + 7 * 4;
  putCount(bytes, ranges_at, 0x3f5a0000u);  // the 4 GB of floats bag_fuzzer found
  const auto problem = laserScanBoundsProblem(bytes.data(), bytes.size());
  EXPECT_NE(problem.find("'ranges'"), std::string::npos) << problem;
  putCount(bytes, ranges_at, 359);  // one short: the intensities count lands in the wrong place
  EXPECT_NE(laserScanBoundsProblem(bytes.data(), bytes.size()), "");
}

TEST(MessageBounds, CutOffAndOverlongMessagesAreRefused) {
  const auto bytes = serialized(scan());
  EXPECT_NE(laserScanBoundsProblem(bytes.data(), 10), "");
  auto longer = bytes;
  longer.push_back(0);
  EXPECT_NE(laserScanBoundsProblem(longer.data(), longer.size()).find("left over"), std::string::npos);
  tf2_msgs::TFMessage tf;
  tf.transforms.resize(1);
  auto tf_bytes = serialized(tf);
  putCount(tf_bytes, 0, 100000000u);
  EXPECT_NE(tfMessageBoundsProblem(tf_bytes.data(), tf_bytes.size()).find("'transforms'"), std::string::npos);
}

}  // namespace
}  // namespace krp::ros1
