// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>

#include "mrpt_krp_plugin/filter/odometry_tracker.h"
#include "mrpt_krp_plugin/filter/seeded_initializer.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "support/test_maps.h"

namespace krp {
namespace {

/// A stand-in relocalizer: one hypothesis 0.2 m and 3 deg off the first pose of the trial.
std::shared_ptr<SeededInitializer> seededNear(const mrpt::math::TPose2D& truth, int* calls) {
  return std::make_shared<SeededInitializer>([truth, calls](const auto&) {
    ++*calls;
    PoseHypothesis h;
    h.pose = mrpt::math::TPose2D(truth.x + 0.2, truth.y - 0.1, truth.phi + 0.05);
    h.cov.setZero();
    h.cov(0, 0) = h.cov(1, 1) = 0.09;
    h.cov(2, 2) = 0.01;
    h.confidence = 1.0;
    Ranking r;
    r.hypotheses = {h};
    r.localized = true;
    return r;
  });
}

TEST(OdometryTracker, MapToOdomPutsTheOdometryPoseOnTheTruth) {
  const auto room = std::make_shared<const mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  TrialParams tp;
  tp.steps = 12;
  const Trial t = generateTrial(*room, lidarProfileByName("omni_12m"), tp, 7);
  int calls = 0;
  OdometryTracker tracker(room, seededNear(t.truth[0], &calls));
  // The odometry frame starts anywhere: a robot's odom origin is where it was switched on.
  mrpt::poses::CPose2D odom(10.0, -3.0, 1.0);
  int updates = 0;
  for (size_t i = 0; i < t.scans.size(); ++i) {
    odom = odom + t.odometry[i];
    if (tracker.update(t.scans[i], odom.asTPose())) ++updates;
  }
  ASSERT_TRUE(tracker.last().has_value());
  EXPECT_EQ(calls, 1);
  EXPECT_GE(updates, 2);
  const mrpt::poses::CPose2D in_map = mrpt::poses::CPose2D(tracker.last()->map_to_odom) + odom;
  const auto& truth = t.truth.back();
  EXPECT_NEAR(in_map.x(), truth.x, 0.25);
  EXPECT_NEAR(in_map.y(), truth.y, 0.25);
  EXPECT_NEAR(mrpt::math::wrapToPi(in_map.phi() - truth.phi), 0.0, 0.1);
}

TEST(OdometryTracker, StandingStillDoesNotUpdateButReinitializeDoes) {
  const auto room = std::make_shared<const mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  TrialParams tp;
  tp.steps = 1;
  const Trial t = generateTrial(*room, lidarProfileByName("omni_12m"), tp, 3);
  int calls = 0;
  OdometryTracker tracker(room, seededNear(t.truth[0], &calls));
  const mrpt::math::TPose2D odom(1, 2, 0.3);
  const auto first = tracker.update(t.scans[0], odom);
  ASSERT_TRUE(first.has_value());
  EXPECT_TRUE(first->estimate.initialized);
  EXPECT_FALSE(tracker.update(t.scans[0], odom).has_value());
  tracker.reinitialize();
  const auto again = tracker.update(t.scans[0], odom);
  ASSERT_TRUE(again.has_value());
  EXPECT_TRUE(again->estimate.initialized);
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace krp
