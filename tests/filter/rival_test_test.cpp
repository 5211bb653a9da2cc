// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/rival_test.h"

#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/sensor_model.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "support/test_maps.h"

namespace krp {
namespace {

// The asymmetric room's pose and its 180 deg twin: most walls agree, the L wall does not.
const mrpt::math::TPose2D kTruth(5.52, 2.07, 0.8);
const mrpt::math::TPose2D kTwin(9.0 - 5.52, 7.0 - 2.07, mrpt::math::wrapToPi(0.8 + M_PI));

mrpt::obs::CObservation2DRangeScan::Ptr scanAt(const mrpt::maps::COccupancyGridMap2D& room, const mrpt::math::TPose2D& pose,
                                               uint64_t seed) {
  Rng rng(seed);
  return ScanSimulator(lidarProfileByName("omni_12m")).simulate(room, mrpt::poses::CPose2D(pose), rng);
}

/// The room with the filter's own sensor model, as MclLocalizer weighs scans on it.
mrpt::maps::COccupancyGridMap2D roomAsTheFilterSeesIt() {
  auto room = test::asymmetricRoom();
  useSensorModel(room, SensorModelParams{});
  return room;
}

/// Feeds scans taken at the truth until the test decides (or `max_scans` pass).
RivalTest::Verdict decide(RivalTest& test, const mrpt::maps::COccupancyGridMap2D& room, const mrpt::math::TPose2D& tracked,
                          int max_scans, int* scans_used = nullptr) {
  auto verdict = RivalTest::Verdict::undecided;
  int n = 0;
  while (verdict == RivalTest::Verdict::undecided && n < max_scans) verdict = test.update(room, *scanAt(room, kTruth, 100 + n++), tracked);
  if (scans_used) *scans_used = n;
  return verdict;
}

TEST(RivalTest, ScansDecideForThePoseTheyWereTakenAt) {
  const auto room = roomAsTheFilterSeesIt();
  RivalTest twin_as_rival(kTwin);
  EXPECT_EQ(decide(twin_as_rival, room, kTruth, 5), RivalTest::Verdict::tracked_wins);
  EXPECT_GT(twin_as_rival.logRatio(), 0.0);
  RivalTest truth_as_rival(kTruth);
  EXPECT_EQ(decide(truth_as_rival, room, kTwin, 5), RivalTest::Verdict::rival_wins);
  EXPECT_LT(truth_as_rival.logRatio(), 0.0);
}

// A rival decided against is watched with its lead held at the bar: fresh evidence the other
// way needs to undo only that much. Held lower, the same scans undo it.
TEST(RivalTest, AHeldLeadIsUndoneByFewerScans) {
  const auto room = roomAsTheFilterSeesIt();
  RivalTest test(kTwin);
  for (int i = 0; i < 5; ++i) test.update(room, *scanAt(room, kTruth, 200 + i), kTruth);
  const double bar = RivalTestParams{}.decisive_log_ratio;
  ASSERT_GT(test.logRatio(), bar) << "five scans gave more than the bar";
  test.holdLeadAt(bar);
  EXPECT_DOUBLE_EQ(test.logRatio(), bar);
  test.holdLeadAt(2.0 * bar);
  EXPECT_DOUBLE_EQ(test.logRatio(), bar) << "holding never raises the lead";
  RivalTest unheld(kTwin);
  for (int i = 0; i < 5; ++i) unheld.update(room, *scanAt(room, kTruth, 200 + i), kTruth);
  // The scans now come from the twin (the robot was there all along): the held lead falls to
  // zero first.
  int scans_held = 0, scans_unheld = 0;
  while (test.logRatio() > 0.0 && scans_held < 50) test.update(room, *scanAt(room, kTwin, 300 + scans_held++), kTruth);
  while (unheld.logRatio() > 0.0 && scans_unheld < 50) unheld.update(room, *scanAt(room, kTwin, 300 + scans_unheld++), kTruth);
  EXPECT_LE(test.logRatio(), 0.0);
  EXPECT_LT(scans_held, scans_unheld);
}

// The same place a few centimetres and a degree off (as the matcher's grid gives it) is no
// evidence against either: re-fitting both poses keeps the ratio near zero; without it, the
// offset copy loses.
TEST(RivalTest, ARivalAFewCentimetresOffIsReFittedBeforeItIsJudged) {
  const auto room = roomAsTheFilterSeesIt();
  const mrpt::math::TPose2D offset(kTruth.x + 0.04, kTruth.y - 0.04, kTruth.phi + 1.0 * M_PI / 180.0);
  RivalTest refitted(offset);
  int scans = 0;
  EXPECT_EQ(decide(refitted, room, kTruth, 8, &scans), RivalTest::Verdict::undecided) << "after " << scans << " scans";
  EXPECT_LT(std::abs(refitted.logRatio()), RivalTestParams{}.decisive_log_ratio);
  RivalTestParams rigid;
  rigid.refine_step_m = 0.0;
  rigid.refine_step_deg = 0.0;
  RivalTest not_refitted(offset, rigid);
  EXPECT_EQ(decide(not_refitted, room, kTruth, 8), RivalTest::Verdict::tracked_wins)
      << "log ratio " << not_refitted.logRatio() << " (refitted: " << refitted.logRatio() << ")";
}

TEST(RivalTest, MovesTheRivalWithTheOdometry) {
  RivalTest t(mrpt::math::TPose2D(2.0, 3.0, 0.0));
  t.move(mrpt::poses::CPose2D(1.0, 0.0, M_PI / 2));
  EXPECT_NEAR(t.rival().x, 3.0, 1e-12);
  EXPECT_NEAR(t.rival().y, 3.0, 1e-12);
  t.move(mrpt::poses::CPose2D(1.0, 0.0, 0.0));  // forward in its own frame: now along +y
  EXPECT_NEAR(t.rival().x, 3.0, 1e-12);
  EXPECT_NEAR(t.rival().y, 4.0, 1e-12);
  EXPECT_NEAR(t.rival().phi, M_PI / 2, 1e-12);
}

TEST(RivalTest, RefusesAZeroBar) {
  RivalTestParams p;
  p.decisive_log_ratio = 0.0;
  EXPECT_THROW(RivalTest({}, p), std::invalid_argument);
}

}  // namespace
}  // namespace krp
