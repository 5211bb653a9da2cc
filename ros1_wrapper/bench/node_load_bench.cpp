// SPDX-License-Identifier: BSD-3-Clause
// Load bench for krp_relocalizer_node (relocalize mode): scans at `rate_hz` (10x a 10 Hz lidar by
// default) while `~relocalize` is called back to back, for `duration_s`. Measures the answer
// latency, how old the scan behind each published initialpose was when it came out (a node that
// queued scans would fall further and further behind), and the node's resident memory over time.
//   krp_ros_node_load WORLD.yaml NODE_PID DURATION_S RATE_HZ OUT.md
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <map>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "ros_conversions.h"

namespace {

double residentMiB(int pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return -1.0;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(std::min<double>(v.size() - 1, p * (v.size() - 1) + 0.5))];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: krp_ros_node_load WORLD.yaml NODE_PID DURATION_S RATE_HZ OUT.md\n";
    return 2;
  }
  ros::init(argc, argv, "krp_node_load", ros::init_options::AnonymousName);
  const auto world = krp::readWorld(argv[1]);
  const int node_pid = std::stoi(argv[2]);
  const double duration_s = std::stod(argv[3]), rate_hz = std::stod(argv[4]);
  const auto map = krp::loadOccupancyMap(world.map_path);
  const auto trial = krp::generateTrial(*map.grid, world.lidar(world.default_lidar_profile), krp::TrialParams{}, 5);

  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  auto scan_pub = nh.advertise<sensor_msgs::LaserScan>("scan", 10);
  std::mutex mutex;
  std::vector<double> staleness_s;
  auto pose_sub = nh.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
      "initialpose", 10, [&](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        staleness_s.push_back((ros::Time::now() - m->header.stamp).toSec());
      });
  tf2_ros::StaticTransformBroadcaster statics;
  tf2_ros::TransformBroadcaster tf;
  statics.sendTransform(krp::ros1::transformToRos({0, 0, 0}, "base_link", "laser", ros::Time::now()));
  if (!ros::service::waitForService("krp_relocalizer/relocalize", ros::Duration(30))) {
    std::cerr << "the node's ~relocalize never appeared\n";
    return 1;
  }

  std::atomic<bool> stop{false};
  std::atomic<long> scans_sent{0};
  auto scan_msg = krp::ros1::scanToRos(*trial.scans[0], ros::Time::now(), "laser");
  std::thread publisher([&] {
    ros::WallRate rate(rate_hz);
    while (!stop) {
      const ros::Time now = ros::Time::now();
      tf.sendTransform(krp::ros1::transformToRos({0, 0, 0}, "odom", "base_link", now));
      scan_msg.header.stamp = now;
      scan_pub.publish(scan_msg);
      ++scans_sent;
      rate.sleep();
    }
  });

  // Warm-up, not measured: until the node has a scan to answer from.
  for (const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(30.0); ros::WallTime::now() < until;) {
    std_srvs::Trigger trigger;
    if (ros::service::call("krp_relocalizer/relocalize", trigger) && trigger.response.success) break;
    ros::WallDuration(0.1).sleep();
  }
  {
    std::lock_guard<std::mutex> lock(mutex);
    staleness_s.clear();
  }
  scans_sent = 0;

  std::vector<double> latency_ms;
  std::vector<std::pair<double, double>> rss;  // (t [s], MiB)
  int answered = 0, localized = 0, calls = 0;
  std::map<std::string, int> refusals;  // why not localized, by message start
  const ros::WallTime start = ros::WallTime::now();
  double last_rss_t = -1;
  while ((ros::WallTime::now() - start).toSec() < duration_s) {
    const double t = (ros::WallTime::now() - start).toSec();
    if (t - last_rss_t >= 1.0) {
      rss.emplace_back(t, residentMiB(node_pid));
      last_rss_t = t;
    }
    std_srvs::Trigger trigger;
    const ros::WallTime call = ros::WallTime::now();
    ++calls;
    if (ros::service::call("krp_relocalizer/relocalize", trigger)) {
      ++answered;
      localized += trigger.response.success ? 1 : 0;
      if (!trigger.response.success) ++refusals[trigger.response.message.substr(0, 60)];
      latency_ms.push_back((ros::WallTime::now() - call).toSec() * 1e3);
    }
  }
  stop = true;
  publisher.join();
  ros::WallDuration(1.0).sleep();
  const bool alive = residentMiB(node_pid) > 0;
  rss.emplace_back((ros::WallTime::now() - start).toSec(), residentMiB(node_pid));

  std::ostringstream r;
  r.precision(3);
  r << "# krp_relocalizer_node under load\n\n"
    << "Command: `scripts/bench_ros_node_load.sh " << duration_s << " " << rate_hz
    << "` (roscore + the node + `krp_ros_node_load`, on one machine).\n\n"
    << "The node keeps no scan queue: the subscription holds 1 message and the relocalizer one "
    << "waiting request, so the age of the scan behind each answer stays at one relocalization's "
    << "duration instead of growing, and memory stays flat.\n\n"
    << "World `" << world.name << "`, lidar `" << world.default_lidar_profile << "`, backend global-matcher, relocalize "
    << "mode. Scans published at " << rate_hz << " Hz for " << duration_s << " s while `~relocalize` is called back to back.\n\n"
    << "| figure | value |\n|---|---|\n"
    << "| scans published | " << scans_sent << " |\n"
    << "| `~relocalize` calls answered | " << answered << " of " << calls << " (" << localized << " localized) |\n"
    << "| relocalizations per scan published | " << static_cast<double>(answered) / std::max<long>(1, scans_sent) << " |\n"
    << "| answer latency median / p95 / max [ms] | " << percentile(latency_ms, 0.5) << " / "
    << percentile(latency_ms, 0.95) << " / " << percentile(latency_ms, 1.0) << " |\n";
  {
    std::lock_guard<std::mutex> lock(mutex);
    r << "| age of the scan behind each initialpose, median / p95 / max [ms] | " << percentile(staleness_s, 0.5) * 1e3
      << " / " << percentile(staleness_s, 0.95) * 1e3 << " / " << percentile(staleness_s, 1.0) * 1e3 << " |\n";
  }
  double rss_min = 1e18, rss_max = 0;
  for (const auto& [t, m] : rss) rss_min = std::min(rss_min, m), rss_max = std::max(rss_max, m);
  r << "| node resident memory first / last / max [MiB] | " << rss.front().second << " / " << rss.back().second << " / "
    << rss_max << " |\n"
    << "| node still running afterwards | " << (alive ? "yes" : "NO") << " |\n\n";
  if (!refusals.empty()) {
    r << "Answers other than a pose:\n\n";
    for (const auto& [why, n] : refusals) r << "- " << n << " x `" << why << "`\n";
    r << "\n";
  }
  r
    << "Memory over time (t [s], RSS [MiB]):";
  for (const auto& [t, m] : rss) r << " (" << static_cast<int>(t) << ", " << m << ")";
  r << "\n";
  std::ofstream(argv[5]) << r.str();
  std::cout << r.str();
  return alive ? 0 : 1;
}
