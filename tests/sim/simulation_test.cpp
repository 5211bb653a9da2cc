// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "support/input_error_message.h"
#include "support/test_maps.h"

namespace krp {
namespace {

TEST(ScanSimulator, ReachesFullRangeDespiteMrptStepLimit) {
  // A long corridor-free box: a wall 11 m ahead must be seen by a 12 m scanner (MRPT's
  // default stepping stops near 0.8 x max range).
  mrpt::maps::COccupancyGridMap2D g(-1, 13, -2, 2, 0.05f);
  for (unsigned y = 0; y < g.getSizeY(); ++y)
    for (unsigned x = 0; x < g.getSizeX(); ++x) g.setCell(x, y, 1.0f);
  for (unsigned y = 0; y < g.getSizeY(); ++y) g.setCell(g.x2idx(11.0), y, 0.0f);
  LidarProfile p = lidarProfileByName("omni_12m");
  p.range_noise_std_m = 0.0;
  p.dropout_probability = 0.0;
  Rng rng(1);
  const auto scan = ScanSimulator(p).simulate(g, mrpt::poses::CPose2D(0, 0, 0), rng);
  ASSERT_EQ(scan->getScanSize(), 720u);
  // Beam pointing straight ahead: index of angle 0 with aperture starting at -aperture/2.
  const size_t ahead = 360;
  EXPECT_TRUE(scan->getScanRangeValidity(ahead));
  EXPECT_NEAR(scan->getScanRange(ahead), 11.0, 0.1);
}

TEST(ScanSimulator, BeyondMaxRangeIsNoReturn) {
  mrpt::maps::COccupancyGridMap2D g(-1, 10, -2, 2, 0.05f);
  for (unsigned y = 0; y < g.getSizeY(); ++y)
    for (unsigned x = 0; x < g.getSizeX(); ++x) g.setCell(x, y, 1.0f);
  for (unsigned y = 0; y < g.getSizeY(); ++y) g.setCell(g.x2idx(8.0), y, 0.0f);
  Rng rng(1);
  const auto scan = ScanSimulator(lidarProfileByName("lds01")).simulate(g, mrpt::poses::CPose2D(0, 0, 0), rng);
  EXPECT_FALSE(scan->getScanRangeValidity(180));  // wall at 8 m, LDS-01 reaches 3.5 m
}

TEST(Trial, SameSeedSameScansDifferentSeedDifferent) {
  const auto room = test::asymmetricRoom();
  const auto lidar = lidarProfileByName("omni_12m");
  TrialParams p;
  p.steps = 5;
  const Trial a = generateTrial(room, lidar, p, 11), b = generateTrial(room, lidar, p, 11), c = generateTrial(room, lidar, p, 12);
  ASSERT_EQ(a.scans.size(), 6u);
  for (size_t i = 0; i < a.scans.size(); ++i) {
    EXPECT_EQ(a.truth[i].x, b.truth[i].x);
    for (size_t k = 0; k < a.scans[i]->getScanSize(); ++k)
      ASSERT_EQ(a.scans[i]->getScanRange(k), b.scans[i]->getScanRange(k)) << "step " << i << " beam " << k;
  }
  EXPECT_NE(a.truth[0].x, c.truth[0].x);
}

TEST(Trial, PathStepsAreSmallAndStayInFreeSpace) {
  const auto room = test::asymmetricRoom();
  TrialParams p;
  p.steps = 30;
  const Trial t = generateTrial(room, lidarProfileByName("lds01"), p, 3);
  for (size_t i = 1; i < t.truth.size(); ++i) {
    const double d = std::hypot(t.truth[i].x - t.truth[i - 1].x, t.truth[i].y - t.truth[i - 1].y);
    EXPECT_LE(d, p.step_length_m + 1e-9);
    EXPECT_LE(std::abs(mrpt::math::wrapToPi(t.truth[i].phi - t.truth[i - 1].phi)), p.max_turn_deg * M_PI / 180 + 1e-9);
    EXPECT_GT(room.getPos(t.truth[i].x, t.truth[i].y), 0.6) << "step " << i << " is in free space";
  }
}

TEST(Trial, StartsInsideTheStartRegion) {
  const auto room = test::asymmetricRoom();
  TrialParams p;
  p.steps = 0;
  p.start_region = {{1.0, 1.0}, {3.0, 1.0}, {3.0, 3.0}, {1.0, 3.0}};
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const auto start = generateTrial(room, lidarProfileByName("lds01"), p, seed).truth.front();
    EXPECT_TRUE(start.x >= 1.0 && start.x <= 3.0 && start.y >= 1.0 && start.y <= 3.0) << start.x << " " << start.y;
  }
  p.start_region = {{-5.0, -5.0}, {-4.0, -5.0}, {-4.0, -4.0}};  // outside the map
  EXPECT_THROW(generateTrial(room, lidarProfileByName("lds01"), p, 1), InputError);
}

TEST(Trial, ClutterChangesScansButNotTheMap) {
  const auto room = test::asymmetricRoom();
  const auto lidar = lidarProfileByName("omni_12m");
  TrialParams clean, cluttered;
  clean.clutter = ClutterParams{0, 0.3, 0.8, 0, 0, 0.2};
  cluttered.clutter.boxes_per_100m2 = 20.0;
  const auto before = countFreeCells(room);
  const Trial a = generateTrial(room, lidar, clean, 5), b = generateTrial(room, lidar, cluttered, 5);
  EXPECT_EQ(countFreeCells(room), before);
  double diff = 0;
  for (size_t k = 0; k < a.scans[0]->getScanSize(); ++k) diff += std::abs(a.scans[0]->getScanRange(k) - b.scans[0]->getScanRange(k));
  EXPECT_GT(diff, 0.0);
}

TEST(Trial, KidnapCarriesTheRobotWithoutOdometry) {
  const auto room = test::asymmetricRoom();
  TrialParams p;
  p.steps = 3;
  const auto a = generateTrial(room, lidarProfileByName("omni_12m"), p, 1);
  const auto b = generateTrial(room, lidarProfileByName("omni_12m"), p, 2);
  const auto k = kidnapTrial(a, b);
  ASSERT_EQ(k.truth.size(), 8u);
  ASSERT_EQ(k.scans.size(), 8u);
  EXPECT_EQ(k.scans[4], b.scans[0]);
  EXPECT_DOUBLE_EQ(k.truth[4].x, b.truth[0].x);
  // The carry shows no motion; the next step's odometry is the second trial's.
  EXPECT_DOUBLE_EQ(k.odometry[4].norm(), 0.0);
  EXPECT_DOUBLE_EQ(k.odometry[5].x(), b.odometry[1].x());
  // The carried distance is not walked.
  EXPECT_DOUBLE_EQ(k.distance_m[4], a.distance_m[3]);
  EXPECT_DOUBLE_EQ(k.distance_m[7], a.distance_m[3] + b.distance_m[3]);
}

TEST(Rawlog, WritesAndReadsBackTheSameSteps) {
  const auto dir = test::tempDir("rawlog");
  const auto room = test::asymmetricRoom();
  TrialParams p;
  p.steps = 4;
  const Trial t = generateTrial(room, lidarProfileByName("lds01"), p, 9);
  writeTrialRawlog(t, dir + "/t.rawlog", dir + "/t_gt.txt");
  const auto steps = readRawlog(dir + "/t.rawlog");
  ASSERT_EQ(steps.size(), 5u);
  auto scan = steps[2].observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->getScanRange(10), t.scans[2]->getScanRange(10));
  std::vector<double> dist;
  const auto gt = readGroundTruth(dir + "/t_gt.txt", &dist);
  ASSERT_EQ(gt.size(), 5u);
  EXPECT_NEAR(gt[3].x, t.truth[3].x, 1e-6);
  EXPECT_NEAR(dist[4], t.distance_m[4], 1e-6);
}

TEST(Rawlog, RejectsTruncatedAndForeignFiles) {
  const auto dir = test::tempDir("rawlog_bad");
  test::writeText(dir + "/junk.rawlog", "not a rawlog");
  EXPECT_THROW(readRawlog(dir + "/junk.rawlog"), InputError);
  EXPECT_THROW(readRawlog(dir + "/missing.rawlog"), InputError);
  test::writeText(dir + "/gt.txt", "0 1 2\n");
  EXPECT_THROW(readGroundTruth(dir + "/gt.txt"), InputError);
}

// A rawlog the rawlog fuzzer found: MRPT's deserializer reads through a null pointer in
// CActionRobotMovement2D::serializeFrom. readRawlog must turn that into an InputError naming the file.
TEST(Rawlog, MrptsCrashOnACorruptRecordBecomesAnInputError) {
  const std::string crasher = std::string(KRP_SOURCE_DIR) + "/tests/fuzz/corpus/rawlog_fuzzer/mrpt_null_action_segv_crash";
  const std::string message = test::inputErrorMessage([&] { readRawlog(crasher); });
  EXPECT_NE(message.find(crasher), std::string::npos) << message;
  EXPECT_NE(message.find("the file is corrupt"), std::string::npos) << message;
}

TEST(World, ReadsTheShippedWorldsAndRejectsBadKeys) {
  for (const char* name : {"office_two_zone", "warehouse", "large_floor", "office_unseen_wing"}) {
    const auto w = readWorld(std::string(KRP_SOURCE_DIR) + "/sim_worlds/" + name + "/" + name + ".world.yaml");
    EXPECT_EQ(w.name, name);
    EXPECT_EQ(w.trial_start_zone, std::string(name) == "office_unseen_wing" ? "unseen_wing" : "");
    EXPECT_EQ(w.lidar(w.default_lidar_profile).name, "omni_12m");
    EXPECT_THROW(w.lidar("laser_pointer"), InputError);
  }
  const auto dir = test::tempDir("world_bad");
  test::writeText(dir + "/w.world.yaml", "name: w\nmap: m.yaml\nzones: z.yaml\nlidar_profiles: [omni_12m]\nspeed: 3\n");
  EXPECT_THROW(readWorld(dir + "/w.world.yaml"), InputError);
  test::writeText(dir + "/p.world.yaml", "name: w\nmap: m.yaml\nzones: z.yaml\nlidar_profiles: [sonar]\n");
  EXPECT_THROW(readWorld(dir + "/p.world.yaml"), InputError);
  test::writeText(dir + "/z.world.yaml", "name: w\nmap: m.yaml\nzones: z.yaml\nlidar_profiles: [omni_12m]\ntrial_start_zone: [a]\n");
  EXPECT_THROW(readWorld(dir + "/z.world.yaml"), InputError);
  // Found by zones_world_fuzzer: a section given as a scalar let yaml-cpp's exception out.
  test::writeText(dir + "/s.world.yaml",
                  "name: w\nmap: m.yaml\nzones: z.yaml\nlidar_profiles: [omni_12m]\nclutter: 3\n");
  try {
    readWorld(dir + "/s.world.yaml");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.world.yaml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace krp
