// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/rival_test.h"

#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/see_through.h"
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

// The best over the 3 x 3 x 3 refinement grid around `pose`: of the likelihood less the
// see-through penalty (`charge_in_fit`), or of the likelihood, charged at its best pose.
double bestOverGrid(const mrpt::maps::COccupancyGridMap2D& room, const mrpt::obs::CObservation2DRangeScan& scan,
                    const SeeThroughPenalty::Scan& see_through, const mrpt::math::TPose2D& pose, bool charge_in_fit) {
  const RivalTestParams p;
  double best = -1e300, charged_at_best = 0.0;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dphi = -1; dphi <= 1; ++dphi) {
        const mrpt::math::TPose2D q(pose.x + dx * p.refine_step_m, pose.y + dy * p.refine_step_m,
                                    mrpt::math::wrapToPi(pose.phi + dphi * p.refine_step_deg * M_PI / 180.0));
        const double ll = room.computeObservationLikelihood(scan, mrpt::poses::CPose3D(mrpt::poses::CPose2D(q)));
        const double score = charge_in_fit ? ll - see_through.nats(q) : ll;
        if (score > best) best = score, charged_at_best = charge_in_fit ? score : ll - see_through.nats(q);
      }
  return charged_at_best;
}

// The room's twin pose sees through the L wall's end: with the penalty in the fit, each side is
// re-fitted to the likelihood less the penalty; without, the penalty is charged where the
// likelihood alone puts it.
TEST(RivalTest, WithTheChargeInTheFitEachSideIsFittedToTheWholeModel) {
  const auto room = roomAsTheFilterSeesIt();
  const SeeThroughPenalty penalty(room, SensorModelParams{});
  const auto scan = scanAt(room, kTruth, 500);
  const auto see_through = penalty.forScan(*scan);
  ASSERT_GT(see_through.count(kTwin), 0) << "the twin pose sees through a wall";
  std::vector<double> ratios;
  for (const bool charge_in_fit : {false, true}) {
    RivalTestParams p;
    p.refit_charges_see_through = charge_in_fit;
    p.finer_refinements = 0;  // bestOverGrid is the first grid
    RivalTest test(kTwin, p);
    test.update(room, *scan, kTruth, &see_through);
    const double expected = bestOverGrid(room, *scan, see_through, kTruth, charge_in_fit) -
                            bestOverGrid(room, *scan, see_through, kTwin, charge_in_fit);
    EXPECT_NEAR(test.logRatio(), expected, 1e-9) << "charge in fit: " << charge_in_fit;
    ratios.push_back(test.logRatio());
  }
  EXPECT_GT(std::abs(ratios[1] - ratios[0]), 0.5) << "on this scan the two fits differ (148.3 against 146.8 nats)";
}

// Two identical rooms, the tracked pose where the scans were taken, the rival in the copy just
// under half a step off in x, y and heading (as a place rounded to the matcher's grid can be):
// the scans cannot tell the rooms apart. Re-fitted on the 5 cm / 1 deg grid alone, the rival
// stays that far off its best (no grid neighbour is nearer) and loses nats on every scan for it
// alone (in this 8 m room, 13.8 nats in 20 scans); with the finer grids the test stays near zero
// (-0.4).
TEST(RivalTest, AnExactCopyStaysUndecidedWhenBothSidesAreFittedFinely) {
  auto rooms = test::twinRooms();
  useSensorModel(rooms, SensorModelParams{});
  const double shift = test::twinRoomsShiftM();
  const double off = 0.45;  // of a step
  const double off_m = off * RivalTestParams{}.refine_step_m;
  const double off_rad = off * RivalTestParams{}.refine_step_deg * M_PI / 180.0;
  const mrpt::math::TPose2D copy(kTruth.x + shift + off_m, kTruth.y - off_m, kTruth.phi + off_rad);
  const int scans = 20;
  const double bar = RivalTestParams{}.decisive_log_ratio;
  double ratio[2];
  for (const int fine : {0, 1}) {
    RivalTestParams p;
    p.finer_refinements = fine ? RivalTestParams{}.finer_refinements : 0;
    RivalTest test(copy, p);
    for (int i = 0; i < scans; ++i) test.update(rooms, *scanAt(rooms, kTruth, 700 + i), kTruth);
    ratio[fine] = test.logRatio();
  }
  EXPECT_GT(ratio[0], 0.5 * bar) << "the first grid alone, after " << scans << " scans: " << ratio[0] << " nats";
  EXPECT_LT(std::abs(ratio[1]), 0.2 * ratio[0]) << "fitted finely: " << ratio[1] << " nats (first grid alone: " << ratio[0] << ")";
}

TEST(RivalTest, RefusesNegativeRefinements) {
  RivalTestParams p;
  p.finer_refinements = -1;
  EXPECT_THROW(RivalTest({}, p), std::invalid_argument);
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
