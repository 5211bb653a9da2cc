// SPDX-License-Identifier: BSD-3-Clause
// What checking a bag's framing costs against reading it, for uncompressed, bz2 and lz4 chunks:
// readBag checks every record (decompressing compressed chunks) before rosbag reads the bag,
// which decompresses them again. The three bags are timed in turn, repetition after
// repetition, so that a busy machine slows them alike.
//   krp_ros_bag_read_bench WORLD.yaml STEPS REPETITIONS OUT_DIR
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "bag_framing.h"
#include "bag_reader.h"
#include "mrpt_krp_plugin/common/statistics.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "support/trial_bag.h"

namespace {

struct Variant {
  std::string name;
  rosbag::compression::CompressionType compression;
  std::string path;
  std::vector<double> check_ms, read_ms;
};

template <typename F>
double millisecondsOf(F&& work) {
  const auto t0 = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: krp_ros_bag_read_bench WORLD.yaml STEPS REPETITIONS OUT_DIR\n";
    return 2;
  }
  const int steps = std::stoi(argv[2]), repetitions = std::stoi(argv[3]);
  if (steps < 1 || repetitions < 1) {
    std::cerr << "krp_ros_bag_read_bench: STEPS and REPETITIONS must be 1 or more\n";
    return 2;
  }
  const std::filesystem::path out(argv[4]);
  std::filesystem::create_directories(out);
  const auto world = krp::readWorld(argv[1]);
  const auto map = krp::loadOccupancyMap(world.map_path);
  krp::TrialParams tp;
  tp.steps = steps;
  const uint64_t trial_seed = 1;
  const auto trial = krp::generateTrial(*map.grid, world.lidar(world.default_lidar_profile), tp, trial_seed);

  std::vector<Variant> variants = {{"uncompressed", rosbag::compression::Uncompressed, "", {}, {}},
                                   {"bz2", rosbag::compression::BZ2, "", {}, {}},
                                   {"lz4", rosbag::compression::LZ4, "", {}, {}}};
  for (auto& v : variants) {
    v.path = (out / (v.name + ".bag")).string();
    krp::ros1::test::writeTrialBag(trial, v.path, mrpt::math::TPose2D(1.0, -2.0, 0.5), v.compression);
  }
  std::size_t scans = 0;
  for (int r = 0; r < repetitions; ++r)
    for (auto& v : variants) {
      v.check_ms.push_back(millisecondsOf([&] { krp::ros1::checkBagFraming(v.path); }));
      v.read_ms.push_back(millisecondsOf([&] { scans = krp::ros1::readBag(v.path).steps.size(); }));
    }

  std::cout << "Command: `krp_ros_bag_read_bench " << argv[1] << " " << steps << " " << repetitions << " " << argv[4]
            << "`\n\nOne simulated trial of " << scans << " scans (" << world.default_lidar_profile
            << ") written three times as a ROS 1 bag; wall-clock medians over " << repetitions
            << " repetitions, taken in turn. \"read\" is `readBag` (framing check included: what krp-localize "
               "--bag does); \"check\" is `checkBagFraming` alone.\n\n"
            << "| chunks | bag size | check, median ms | read, median ms | check / read |\n|---|---|---|---|---|\n";
  for (const auto& v : variants) {
    const double check = krp::median(v.check_ms), read = krp::median(v.read_ms);
    std::cout << "| " << v.name << " | " << std::filesystem::file_size(v.path) / 1024 << " KiB | " << std::fixed
              << std::setprecision(2) << check << " | " << read << " | " << std::setprecision(0) << 100.0 * check / read
              << " % |\n";
  }
  return 0;
}
