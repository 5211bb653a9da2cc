// SPDX-License-Identifier: BSD-3-Clause
#include "bag_reader.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>
#include <tf2_msgs/TFMessage.h>

#include <mrpt/poses/CPose2D.h>

#include <boost/make_shared.hpp>
#include <filesystem>
#include <vector>

#include "bag_framing.h"
#include "message_bounds.h"
#include "mrpt_krp_plugin/common/input_error.h"

namespace krp::ros1 {

namespace {
// tf2's cache must hold the whole bag: transforms are looked up after all are loaded.
constexpr double kCacheMarginS = 10.0;
// A recording longer than a year is a corrupt stamp, not a log; ros::Duration holds 68 years.
constexpr double kMaxBagLengthS = 365.0 * 24 * 3600;

/// The message, or null when it is of another type (as MessageInstance::instantiate). Its
/// lengths are checked before roscpp sizes anything from them (message_bounds.h).
template <typename Message>
boost::shared_ptr<Message> decodeChecked(const rosbag::MessageInstance& m, const std::string& path,
                                         std::string (*bounds_problem)(const uint8_t*, size_t)) {
  if (!m.isType<Message>()) return nullptr;
  std::vector<uint8_t> bytes(m.size());
  ros::serialization::OStream out(bytes.data(), static_cast<uint32_t>(bytes.size()));
  m.write(out);
  const std::string problem = bounds_problem(bytes.data(), bytes.size());
  if (!problem.empty())
    throw InputError(path, "a " + m.getDataType() + " message on '" + m.getTopic() + "' is corrupt: " + problem);
  auto msg = boost::make_shared<Message>();
  ros::serialization::IStream in(bytes.data(), static_cast<uint32_t>(bytes.size()));
  ros::serialization::deserialize(in, *msg);
  return msg;
}

void loadTransforms(const rosbag::Bag& bag, tf2::BufferCore& buffer, const std::string& path) {
  rosbag::View view(bag, rosbag::TopicQuery(std::vector<std::string>{"/tf", "/tf_static"}));
  for (const auto& m : view) {
    const auto tf = decodeChecked<tf2_msgs::TFMessage>(m, path, tfMessageBoundsProblem);
    if (!tf) continue;
    const bool is_static = m.getTopic() == "/tf_static";
    for (const auto& t : tf->transforms) buffer.setTransform(t, "bag", is_static);
  }
}
}  // namespace

BagSteps readBag(const std::string& path, const BagReadParams& params) {
  if (!std::filesystem::exists(path)) throw InputError(path, "bag file does not exist");
  checkBagFraming(path);
  rosbag::Bag bag;
  try {
    bag.open(path, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& e) {
    throw InputError(path, std::string("not a readable ROS 1 bag: ") + e.what());
  }
  BagSteps out;
  try {
    rosbag::View all(bag);
    if (all.size() == 0) throw InputError(path, "the bag holds no messages");
    // In doubles: ros::Time subtraction throws std::runtime_error when a corrupt stamp puts the
    // span beyond 32-bit seconds (found by bag_fuzzer).
    const double length_s = all.getEndTime().toSec() - all.getBeginTime().toSec();
    if (!(length_s >= 0 && length_s <= kMaxBagLengthS))
      throw InputError(path, "the bag's time stamps span " + std::to_string(length_s) +
                                 " s: a stamp is corrupt (at most " + std::to_string(kMaxBagLengthS) + " s are accepted)");
    tf2::BufferCore buffer(ros::Duration(length_s + kCacheMarginS));
    loadTransforms(bag, buffer, path);

    rosbag::View scans(bag, rosbag::TopicQuery(params.scan_topic));
    if (scans.size() == 0) throw InputError(path, "no messages on the scan topic '" + params.scan_topic + "'");
    std::optional<mrpt::poses::CPose2D> previous_odom;
    for (const auto& m : scans) {
      const auto msg = decodeChecked<sensor_msgs::LaserScan>(m, path, laserScanBoundsProblem);
      if (!msg) throw InputError(path, "topic '" + params.scan_topic + "' does not hold sensor_msgs/LaserScan");
      ++out.scans_seen;
      mrpt::poses::CPose3D laser_in_base;
      mrpt::poses::CPose2D odom;
      try {
        const auto laser = buffer.lookupTransform(params.base_frame, msg->header.frame_id, msg->header.stamp);
        const auto l = pose2DFromRos(laser.transform);
        laser_in_base = mrpt::poses::CPose3D(l.x, l.y, laser.transform.translation.z, l.phi, 0, 0);
        odom = mrpt::poses::CPose2D(
            pose2DFromRos(buffer.lookupTransform(params.odom_frame, params.base_frame, msg->header.stamp).transform));
      } catch (const tf2::TransformException& e) {
        ++out.skipped_no_transform;
        if (out.first_problem.empty()) out.first_problem = std::string("no transform: ") + e.what();
        continue;
      }
      mrpt::obs::CObservation2DRangeScan::Ptr scan;
      try {
        scan = scanFromRos(*msg, laser_in_base, params.scan_check);
      } catch (const InputError& e) {
        ++out.skipped_bad_scan;
        if (out.first_problem.empty()) out.first_problem = e.what();
        continue;
      }
      scan->timestamp = mrpt::Clock::fromDouble(msg->header.stamp.toSec());
      out.steps.push_back(
          makeRawlogStep(previous_odom ? odom - *previous_odom : mrpt::poses::CPose2D(), scan, params.odometry));
      previous_odom = odom;
    }
  } catch (const rosbag::BagException& e) {
    throw InputError(path, std::string("bag is truncated or corrupt: ") + e.what());
  } catch (const ros::Exception& e) {
    // A message shorter than its type says (found by bag_fuzzer): roscpp's StreamOverrunException.
    throw InputError(path, std::string("a message in the bag cannot be decoded: ") + e.what());
  } catch (const InputError&) {
    throw;  // already names the bag and the problem
  } catch (const std::runtime_error& e) {
    // rostime and tf2 report out-of-range stamps as std::runtime_error (bag_fuzzer).
    throw InputError(path, std::string("a time stamp in the bag is out of range: ") + e.what());
  }
  if (out.steps.empty())
    throw InputError(path, "none of the " + std::to_string(out.scans_seen) + " scans could be used: " + out.first_problem);
  return out;
}

}  // namespace krp::ros1
