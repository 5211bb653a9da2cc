// SPDX-License-Identifier: BSD-3-Clause
// What the node receives: LaserScan and OccupancyGrid messages with arbitrary field values
// (NaN, inf, negative, sizes that do not match), built from the fuzz input. The first byte
// picks the message. Every bad message must end in an InputError.
#include <fuzzer/FuzzedDataProvider.h>

#include "mrpt_krp_plugin/common/input_error.h"
#include "ros_conversions.h"

namespace {
// Larger grids or scans add nothing a fuzzer can find and slow every run.
constexpr size_t kMaxBeams = 4096;
constexpr uint32_t kMaxGridSide = 512;

float anyFloat(FuzzedDataProvider& in) {
  return in.ConsumeBool() ? in.ConsumeFloatingPoint<float>() : in.ConsumeFloatingPointInRange<float>(-10.f, 40.f);
}

void scan(FuzzedDataProvider& in) {
  sensor_msgs::LaserScan msg;
  msg.header.frame_id = "laser";
  msg.angle_min = anyFloat(in);
  msg.angle_max = anyFloat(in);
  msg.angle_increment = anyFloat(in);
  msg.range_min = anyFloat(in);
  msg.range_max = anyFloat(in);
  const size_t beams = in.ConsumeIntegralInRange<size_t>(0, kMaxBeams);
  for (size_t i = 0; i < beams && in.remaining_bytes() > 0; ++i) msg.ranges.push_back(anyFloat(in));
  const mrpt::poses::CPose3D mount(anyFloat(in), anyFloat(in), 0, anyFloat(in), 0, 0);
  krp::ros1::scanFromRos(msg, mount);
}

void grid(FuzzedDataProvider& in) {
  nav_msgs::OccupancyGrid msg;
  msg.info.width = in.ConsumeIntegralInRange<uint32_t>(0, kMaxGridSide);
  msg.info.height = in.ConsumeIntegralInRange<uint32_t>(0, kMaxGridSide);
  msg.info.resolution = anyFloat(in);
  msg.info.origin.position.x = anyFloat(in);
  msg.info.origin.position.y = anyFloat(in);
  msg.info.origin.orientation.z = anyFloat(in);
  msg.info.origin.orientation.w = anyFloat(in);
  const auto data = in.ConsumeRemainingBytes<int8_t>();
  // Mostly the right size, so that the conversion itself is reached.
  if (!data.empty() && data.front() % 4 != 0) {
    msg.data.resize(static_cast<size_t>(msg.info.width) * msg.info.height);
    for (size_t i = 0; i < msg.data.size(); ++i) msg.data[i] = data[i % data.size()];
  } else {
    msg.data = data;
  }
  krp::ros1::occupancyMapFromRos(msg);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  try {
    if (in.ConsumeBool())
      scan(in);
    else
      grid(in);
  } catch (const krp::InputError&) {
  }
  return 0;
}
