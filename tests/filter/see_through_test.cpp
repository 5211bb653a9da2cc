// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/see_through.h"

#include <gtest/gtest.h>

#include <mrpt/maps/CSimplePointsMap.h>

#include <cmath>
#include <stdexcept>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/rival_test.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/submap/scan_beams.h"
#include "support/test_maps.h"

namespace krp {
namespace {

// In the asymmetric room (walls at x = 0.5 and 8.5); the same heading 1 m further east, where
// the returns of the beams pointing east would lie beyond the east wall.
const mrpt::math::TPose2D kTruth(5.52, 2.07, 0.8);
const mrpt::math::TPose2D kOneMetreEast(6.52, 2.07, 0.8);

mrpt::obs::CObservation2DRangeScan::Ptr scanAt(const mrpt::maps::COccupancyGridMap2D& room, const mrpt::math::TPose2D& pose,
                                               uint64_t seed) {
  Rng rng(seed);
  return ScanSimulator(lidarProfileByName("omni_12m")).simulate(room, mrpt::poses::CPose2D(pose), rng);
}

SensorModelParams everyBeam() {
  SensorModelParams s;
  s.decimation = 1;
  return s;
}

// Nearly nothing: a beam grazing a corner can end a cell or two past where the ray marcher
// meets the corner cell (one of the 720 beams here, ending in the room's north-east corner).
TEST(SeeThrough, AScanSeesThroughNearlyNothingFromWhereItWasTaken) {
  const auto room = test::asymmetricRoom();
  const SeeThroughPenalty penalty(room, everyBeam());
  for (uint64_t seed = 1; seed <= 5; ++seed)
    EXPECT_LE(penalty.count(*scanAt(room, kTruth, seed), kTruth), 2) << "scan " << seed;
  const auto scan = scanAt(room, kTruth, 1);
  const int east = penalty.count(*scan, kOneMetreEast);
  EXPECT_GT(east, 20) << "the beams pointing east end beyond the east wall";
  EXPECT_NEAR(penalty.nats(*scan, kOneMetreEast), east * seeThroughNats(everyBeam()), 1e-9);
}

// The beam pointing due east, square onto the east wall, made 1 m longer ends beyond the wall;
// 0.2 m longer stays within the tolerance (range noise); with no return it says nothing.
TEST(SeeThrough, ABeamIsChargedOnlyForAReturnBeyondTheToleranceBehindAnObstacle) {
  const auto room = test::asymmetricRoom();
  const SeeThroughPenalty penalty(room, everyBeam());
  auto scan = scanAt(room, kTruth, 2);
  const auto beams = scanBeams(*scan);
  size_t east = 0;
  for (size_t i = 0; i < beams.beams.size(); ++i)
    if (std::abs(kTruth.phi + beams.beams[i].angle_rad) < std::abs(kTruth.phi + beams.beams[east].angle_rad)) east = i;
  ASSERT_TRUE(beams.beams[east].hit);
  const int before = penalty.count(*scan, kTruth);
  const float range = scan->getScanRange(east);
  scan->setScanRange(east, range + 0.2f);
  EXPECT_EQ(penalty.count(*scan, kTruth), before);
  scan->setScanRange(east, range + 1.0f);
  EXPECT_EQ(penalty.count(*scan, kTruth), before + 1);
  scan->setScanRangeValidity(east, false);
  EXPECT_EQ(penalty.count(*scan, kTruth), before);
}

TEST(SeeThrough, ChecksEveryDecimationthBeamAsTheLikelihoodFieldDoes) {
  const auto room = test::asymmetricRoom();
  const auto scan = scanAt(room, kTruth, 3);
  SensorModelParams every_fourth;
  every_fourth.decimation = 4;
  const int all = SeeThroughPenalty(room, everyBeam()).count(*scan, kOneMetreEast);
  const int fourth = SeeThroughPenalty(room, every_fourth).count(*scan, kOneMetreEast);
  EXPECT_GT(fourth, 0);
  EXPECT_NEAR(fourth, all / 4.0, 0.1 * all + 2.0);
}

// The charge is what the filter's likelihood field (MRPT's own code) gives a return on an
// obstacle, less what it gives one far from any: a see-through beam scores as a miss.
TEST(SeeThrough, ABeamCostsWhatAMissCostsInTheLikelihoodField) {
  auto room = test::asymmetricRoom();
  const SensorModelParams sensor;
  useSensorModel(room, sensor);
  auto pointLogLikelihood = [&](double x, double y) {
    mrpt::maps::CSimplePointsMap one;
    one.insertPoint(static_cast<float>(x), static_cast<float>(y), 0.0f);
    return room.computeLikelihoodField_Thrun(&one, nullptr);
  };
  // (0.5, 3.0) is on the west wall; (4.5, 5.0) is more than max_corr_distance from every wall.
  ASSERT_LT(room.getPos(0.51, 3.0), 0.35f) << "the test point is on an obstacle cell";
  const double gap = pointLogLikelihood(0.51, 3.0) - pointLogLikelihood(4.5, 5.0);
  EXPECT_NEAR(seeThroughNats(sensor), gap, 1e-4);
  EXPECT_GT(seeThroughNats(sensor), 1.0);
}

// The rival test weighs poses with the same penalty as the particles: one scan taken at the
// truth puts more evidence against the pose that would have seen through the east wall.
TEST(SeeThrough, TheRivalTestChargesTheRivalThatSeesThroughTheMap) {
  auto room = test::asymmetricRoom();
  useSensorModel(room, SensorModelParams{});
  const SeeThroughPenalty penalty(room, SensorModelParams{});
  const auto scan = scanAt(room, kTruth, 4);
  RivalTest likelihood_field_only(kOneMetreEast), with_penalty(kOneMetreEast);
  likelihood_field_only.update(room, *scan, kTruth);
  const auto charged = penalty.forScan(*scan);
  with_penalty.update(room, *scan, kTruth, &charged);
  EXPECT_GT(with_penalty.logRatio(), likelihood_field_only.logRatio() + penalty.perBeamNats());
}

TEST(SeeThrough, RefusesANegativeToleranceOrAnOccupancyOutsideTheUnitInterval) {
  const auto room = test::asymmetricRoom();
  SeeThroughParams p;
  p.tolerance_m = -0.1;
  EXPECT_THROW(SeeThroughPenalty(room, SensorModelParams{}, p), std::invalid_argument);
  p = {};
  p.min_occupancy = 1.0;
  EXPECT_THROW(SeeThroughPenalty(room, SensorModelParams{}, p), std::invalid_argument);
}

// countUpTo may stop once it has found enough: never more than the whole count, at least
// `enough` when there are that many, and the whole count when asked for more.
TEST(SeeThrough, ACountThatMayStopEarlyStopsOnlyOnceItHasEnough) {
  const auto room = test::asymmetricRoom();
  const SeeThroughPenalty penalty(room, everyBeam());
  const auto scan = penalty.forScan(*scanAt(room, kTruth, 4));
  const int all = scan.count(kOneMetreEast);
  ASSERT_GT(all, 20);
  for (int enough : {1, 5, all - 1}) {
    const int some = scan.countUpTo(kOneMetreEast, enough);
    EXPECT_GE(some, enough);
    EXPECT_LE(some, all);
  }
  EXPECT_EQ(scan.countUpTo(kOneMetreEast, all + 1), all);
  EXPECT_DOUBLE_EQ(scan.share(kOneMetreEast), static_cast<double>(all) / scan.checked());
  EXPECT_GE(scan.shareUpTo(kOneMetreEast, 0.05), 0.05);
  EXPECT_DOUBLE_EQ(scan.shareUpTo(kOneMetreEast, 1.0), scan.share(kOneMetreEast));
}

// The rays marched side by side give the count of marching them one at a time, at poses in the
// room, hugging its walls, on them and off the map, and stop at exactly `enough`.
TEST(SeeThrough, RaysMarchedSideBySideCountAsRaysMarchedOneAtATime) {
  const auto room = test::asymmetricRoom();
  const SeeThroughPenalty penalty(room, everyBeam());
  const auto scan = penalty.forScan(*scanAt(room, kTruth, 4));
  Rng rng(17);
  int poses_seeing_through = 0;
  for (int i = 0; i < 400; ++i) {
    // x and y from a little off the map's edges to a little beyond them, any heading.
    const mrpt::math::TPose2D pose(rng.uniform(room.getXMin() - 1.0, room.getXMax() + 1.0),
                                   rng.uniform(room.getYMin() - 1.0, room.getYMax() + 1.0), rng.uniform(-M_PI, M_PI));
    const int one_at_a_time = scan.countOneRayAtATime(pose);
    ASSERT_EQ(scan.count(pose), one_at_a_time) << "pose " << i;
    for (int enough : {0, 1, 3, one_at_a_time, one_at_a_time + 1})
      ASSERT_EQ(scan.countUpTo(pose, enough), std::min(std::max(enough, 0), one_at_a_time)) << "pose " << i;
    poses_seeing_through += one_at_a_time > 0 ? 1 : 0;
  }
  EXPECT_GT(poses_seeing_through, 100) << "too few poses that see through to test the count";
}

}  // namespace
}  // namespace krp
