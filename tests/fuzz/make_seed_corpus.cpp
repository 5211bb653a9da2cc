// SPDX-License-Identifier: BSD-3-Clause
// Writes the fuzzers' seed corpus (committed in corpus/): one small valid input of each kind, so
// that fuzzing starts inside each format rather than at its first check.
//   make_seed_corpus REPO_ROOT OUT_FOLDER
#include <octomap/OcTree.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "mrpt_krp_plugin/map/mrpt_gridmap_reader.h"
#include "mrpt_krp_plugin/map/ros_map_yaml.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "mrpt_krp_plugin/zones/landmarks_yaml.h"
#include "support/test_maps.h"
#ifdef KRP_FUZZ_WITH_ROS1
#include "support/trial_bag.h"
#endif

namespace fs = std::filesystem;

namespace {
// A small room keeps every seed well under the fuzzers' input limit.
constexpr double kRoomWidthM = 3.0, kRoomHeightM = 2.0, kRoomResolutionM = 0.1;

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeBytes(const fs::path& p, const std::string& bytes) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
}

std::string prefixed(char selector, const std::string& bytes) { return std::string(1, selector) + bytes; }

void writeGzip(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  gzFile f = gzopen(p.string().c_str(), "wb");
  gzwrite(f, text.data(), static_cast<unsigned>(text.size()));
  gzclose(f);
}

// A CARMEN log: settings, odometry, two FLASER lines and a ROBOTLASER1 line.
std::string carmenLog() {
  std::ostringstream s;
  s << "# message formats defined: PARAM SYNC ODOM FLASER RLASER\n"
       "PARAM robot_front_laser_max 8.0 nohost 0\nPARAM robot_frontlaser_offset 0.1 nohost 0\n"
       "ODOM 0 0 0 0 0 0 1.0 seed 1.0\n";
  for (int k = 0; k < 2; ++k) {
    s << "FLASER 12";
    for (int i = 0; i < 12; ++i) s << " " << 1.0 + 0.1 * i + k;
    s << " " << k << " 0.5 0.1 " << k << " 0.5 0.1 " << 2 + k << " seed " << 2 + k << "\n";
  }
  s << "ROBOTLASER1 0 -1.57 3.14 0.2618 20.0 0.01 0 13 1 1 1 1 1 2 2 2 2 2 3 3 3 0 1.1 0.5 0.1 1.0 0.5 0.1 0 0 0.5 0.2 "
       "100 4.0 seed 4.0\n";
  return s.str();
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_seed_corpus REPO_ROOT OUT_FOLDER\n";
    return 2;
  }
  const fs::path repo = argv[1], out = argv[2];
  const fs::path scratch = fs::temp_directory_path() / "krp_seed_corpus";
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  const auto room = krp::test::asymmetricRoom(kRoomWidthM, kRoomHeightM, kRoomResolutionM);

  // map_server YAML + image, in each mode.
  krp::writeRosMap(room, (scratch / "room.yaml").string());
  const std::string pgm = readBytes(scratch / "room.pgm");
  const std::string marker = "\n%%IMAGE%%\n";
  const std::string base = "resolution: 0.1\norigin: [-1.0, 2.0, 0.3]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  writeBytes(out / "ros_map_fuzzer/trinary", "image: map.pgm\nnegate: 0\n" + base + marker + pgm);
  writeBytes(out / "ros_map_fuzzer/scale_negate", "image: map.pgm\nmode: scale\nnegate: 1\n" + base + marker + pgm);
  writeBytes(out / "ros_map_fuzzer/raw", "image: map.pgm\nmode: raw\nnegate: 0\n" + base + marker + pgm);
  writeBytes(out / "ros_map_fuzzer/yaml_only", "image: map.pgm\nnegate: 0\n" + base);
  std::vector<uchar> png;
  cv::imencode(".png", cv::imread((scratch / "room.pgm").string(), cv::IMREAD_UNCHANGED), png);
  writeBytes(out / "ros_map_fuzzer/png", "image: map.png\nnegate: 0\n" + base + marker + std::string(png.begin(), png.end()));

  // Binary maps; the first byte picks the format (see binary_map_fuzzer.cpp).
  krp::writeMrptGridmap(room, (scratch / "room.gridmap").string());
  krp::writeMrptGridmap(room, (scratch / "room.gridmap.gz").string());
  writeBytes(out / "binary_map_fuzzer/gridmap", prefixed(0, readBytes(scratch / "room.gridmap")));
  writeBytes(out / "binary_map_fuzzer/gridmap_gz", prefixed(1, readBytes(scratch / "room.gridmap.gz")));
  octomap::OcTree tree(0.2);
  for (double x = 0.1; x < 2.0; x += 0.2)
    for (double y = 0.1; y < 1.4; y += 0.2) {
      const bool wall = x < 0.2 || x > 1.8 || y < 0.2 || y > 1.2;
      tree.updateNode(octomap::point3d(static_cast<float>(x), static_cast<float>(y), 0.5f), wall);
    }
  tree.writeBinary((scratch / "room.bt").string());
  tree.write((scratch / "room.ot").string());
  writeBytes(out / "binary_map_fuzzer/octomap_bt", prefixed(2, readBytes(scratch / "room.bt")));
  writeBytes(out / "binary_map_fuzzer/octomap_ot", prefixed(3, readBytes(scratch / "room.ot")));

  writeBytes(out / "model_manifest_fuzzer/office_two_zone", readBytes(repo / "models/office_two_zone/manifest.json"));

  // Hand-written YAML; the first byte picks the reader (see zones_world_fuzzer.cpp).
  const fs::path world = repo / "sim_worlds/office_two_zone";
  writeBytes(out / "zones_world_fuzzer/zones", prefixed(0, readBytes(world / "office_two_zone.zones.yaml")));
  krp::LandmarkParams lp;
  lp.keypoints_per_zone = 3;
  krp::writeLandmarksYaml({{"west", {{1, 1}, {2, 1}, {1, 2}}}, {"east", {{5, 1}, {6, 2}, {5, 3}}}}, lp,
                          (scratch / "landmarks.yaml").string());
  writeBytes(out / "zones_world_fuzzer/landmarks", prefixed(1, readBytes(scratch / "landmarks.yaml")));
  writeBytes(out / "zones_world_fuzzer/world", prefixed(2, readBytes(world / "office_two_zone.world.yaml")));

  // A two-step trial in the room, as a rawlog, its ground truth and a bag.
  krp::LidarProfile lidar;
  lidar.name = "seed";
  lidar.fov_rad = 2 * M_PI;
  lidar.beams = 36;
  lidar.max_range_m = 4.0;
  krp::TrialParams tp;
  tp.steps = 2;
  tp.clearance_m = 0.2;
  const auto trial = krp::generateTrial(room, lidar, tp, 1);
  krp::writeTrialRawlog(trial, (scratch / "t.rawlog").string(), (scratch / "t_gt.txt").string());
  writeBytes(out / "rawlog_fuzzer/trial", readBytes(scratch / "t.rawlog"));
  writeBytes(out / "ground_truth_fuzzer/trial", readBytes(scratch / "t_gt.txt"));
  writeBytes(out / "carmen_log_fuzzer/flaser_robotlaser", carmenLog());
  writeGzip(out / "carmen_log_fuzzer/flaser_robotlaser_gz", carmenLog());
#ifdef KRP_FUZZ_WITH_ROS1
  krp::ros1::test::writeTrialBag(trial, (scratch / "t.bag").string());
  writeBytes(out / "bag_fuzzer/trial", readBytes(scratch / "t.bag"));
  // Compressed chunks, whose inside the framing check leaves to rosbag's decompressors.
  krp::ros1::test::writeTrialBag(trial, (scratch / "t_bz2.bag").string(), mrpt::math::TPose2D(1.0, -2.0, 0.5),
                                 rosbag::compression::BZ2);
  writeBytes(out / "bag_fuzzer/trial_bz2", readBytes(scratch / "t_bz2.bag"));
  krp::ros1::test::writeTrialBag(trial, (scratch / "t_lz4.bag").string(), mrpt::math::TPose2D(1.0, -2.0, 0.5),
                                 rosbag::compression::LZ4);
  writeBytes(out / "bag_fuzzer/trial_lz4", readBytes(scratch / "t_lz4.bag"));
  // Messages are built field by field from the bytes (see ros_messages_fuzzer.cpp): a few
  // patterns are enough to start from.
  writeBytes(out / "ros_messages_fuzzer/scan", std::string("\x01") + std::string(256, '\x40'));
  writeBytes(out / "ros_messages_fuzzer/grid", std::string("\x00", 1) + std::string(128, '\x10'));
#endif
  fs::remove_all(scratch);
  std::cout << "seed corpus written to " << out << "\n";
  return 0;
}
