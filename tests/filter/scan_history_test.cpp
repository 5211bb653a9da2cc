// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/scan_history.h"

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

// The asymmetric room's pose and its 180 deg twin (as in rival_test_test.cpp): most walls
// agree, the L wall does not.
const mrpt::math::TPose2D kTruth(5.52, 2.07, 0.8);
const mrpt::math::TPose2D kTwin(9.0 - 5.52, 7.0 - 2.07, mrpt::math::wrapToPi(0.8 + M_PI));
const mrpt::poses::CPose2D kStep(0.3, 0.0, 0.0);  // the robot drove 0.3 m ahead between scans

mrpt::obs::CObservation2DRangeScan::Ptr scanAt(const mrpt::maps::COccupancyGridMap2D& room, const mrpt::poses::CPose2D& pose,
                                               uint64_t seed) {
  Rng rng(seed);
  return ScanSimulator(lidarProfileByName("omni_12m")).simulate(room, pose, rng);
}

mrpt::maps::COccupancyGridMap2D roomAsTheFilterSeesIt() {
  auto room = test::asymmetricRoom();
  useSensorModel(room, SensorModelParams{});
  return room;
}

/// Scans taken `n` steps before the truth, oldest first, each stored with the step before it.
ScanHistory pathToTheTruth(const mrpt::maps::COccupancyGridMap2D& room, int n, std::size_t capacity) {
  ScanHistory history(capacity);
  for (int j = n; j >= 1; --j) {
    mrpt::poses::CPose2D at(kTruth);
    for (int k = 0; k < j; ++k) at = at + (-kStep);
    history.push(*scanAt(room, at, 500 + j), std::nullopt, kStep);
  }
  return history;
}

TEST(ScanHistory, KeepsOnlyTheLatestUpdates) {
  const auto room = roomAsTheFilterSeesIt();
  EXPECT_EQ(pathToTheTruth(room, 5, 3).size(), 3u);
  EXPECT_EQ(pathToTheTruth(room, 5, 0).size(), 0u) << "capacity 0 keeps nothing";
}

TEST(ScanHistory, AnEmptyHistoryPrimesNothing) {
  const auto room = roomAsTheFilterSeesIt();
  const ScanHistory empty(4);
  const auto test = empty.primedTest(kTwin, kTruth, kStep, room, RivalTestParams{});
  EXPECT_DOUBLE_EQ(test.logRatio(), 0.0);
  EXPECT_DOUBLE_EQ(test.rival().x, kTwin.x);
  EXPECT_DOUBLE_EQ(test.rival().phi, kTwin.phi);
}

// The twin is weighed on the scans the robot took on its way to the truth, moved back as a twin
// robot would have driven: those scans already favour the truth, so the primed test starts with
// a lead that a test started on the current scan alone does not have, and its rival ends where
// it was found (driven back and forth by the same odometry, re-fitted on the way).
TEST(ScanHistory, TheScansOnTheWayFavourThePoseTheyWereTakenFrom) {
  const auto room = roomAsTheFilterSeesIt();
  const auto history = pathToTheTruth(room, 3, 3);
  const auto primed = history.primedTest(kTwin, kTruth, kStep, room, RivalTestParams{});
  EXPECT_GT(primed.logRatio(), 0.0);
  EXPECT_LT(std::hypot(primed.rival().x - kTwin.x, primed.rival().y - kTwin.y), 0.2);

  auto primed_then_now = primed;
  RivalTest fresh(kTwin);
  const auto now = scanAt(room, mrpt::poses::CPose2D(kTruth), 600);
  primed_then_now.update(room, *now, kTruth);
  fresh.update(room, *now, kTruth);
  EXPECT_GT(primed_then_now.logRatio(), fresh.logRatio());

  // Taken on the twin's side of the room instead, the same scans favour the twin.
  const auto from_twin = history.primedTest(kTruth, kTwin, kStep, room, RivalTestParams{});
  EXPECT_LT(from_twin.logRatio(), 0.0);
}

}  // namespace
}  // namespace krp
