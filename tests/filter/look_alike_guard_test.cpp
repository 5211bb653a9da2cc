// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/look_alike_guard.h"

#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cmath>
#include <vector>

#include "mrpt_krp_plugin/bench/method_registry.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/filter/sensor_model.h"
#include "mrpt_krp_plugin/filter/see_through.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/relocalize/relocalizer.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"
#include "support/test_maps.h"

namespace krp {
namespace {

// The 8 x 6 m asymmetric room: a pose and its 180 deg twin share most walls; only the L wall
// and the block tell them apart, so the twin fits the truth's scan less well.
const mrpt::math::TPose2D kTruth(5.52, 2.07, 0.8);
const mrpt::math::TPose2D kTwin(9.0 - 5.52, 7.0 - 2.07, mrpt::math::wrapToPi(0.8 + M_PI));
/// More than the twin's matcher score falls short of the truth's on the truth's scans.
constexpr double kTwinShortfallBound = 0.3;

mrpt::obs::CObservation2DRangeScan::Ptr scanAtTruth(const mrpt::maps::COccupancyGridMap2D& room, uint64_t seed) {
  Rng rng(seed);
  return ScanSimulator(lidarProfileByName("omni_12m")).simulate(room, mrpt::poses::CPose2D(kTruth), rng);
}

double distance(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

/// A filter step holding `scan` and no odometry (the robot stands still).
RawlogStep stepWithScan(mrpt::obs::CObservation2DRangeScan::Ptr scan) {
  RawlogStep step;
  step.observations = mrpt::obs::CSensoryFrame::Create();
  step.observations->insert(std::move(scan));
  return step;
}

LookAlikeGuardParams withAmbiguityMargin(double margin) {
  LookAlikeGuardParams p;
  p.ambiguity_margin = margin;
  return p;
}

TEST(LookAlikeGuard, FindsTheBetterPlaceOnlyFromTheWrongOne) {
  const auto room = test::asymmetricRoom();
  const LookAlikeGuard guard(std::make_shared<CorrelativeMatcher>(room), withAmbiguityMargin(0.0));
  const auto scan = scanAtTruth(room, 1);
  const auto from_twin = guard.lookAlike(*scan, kTwin);
  ASSERT_TRUE(from_twin.has_value());
  EXPECT_LT(distance(from_twin->pose, kTruth), 0.2);
  EXPECT_GT(from_twin->score, from_twin->tracked_score);
  EXPECT_TRUE(guard.fitsAtLeastAsWell(*from_twin));
  EXPECT_FALSE(guard.lookAlike(*scan, kTruth).has_value()) << "the twin fits worse than the truth";
}

// The wall-heading windows keep the search to the headings that line the scan's walls up with
// the room's: the twin's truth is found as over the full turn, for fewer nodes.
TEST(LookAlikeGuard, AWallHeadingWindowFindsTheSameLookAlikeForFewerNodes) {
  const auto room = test::asymmetricRoom();
  const auto matcher = std::make_shared<CorrelativeMatcher>(room);
  LookAlikeGuardParams windowed = withAmbiguityMargin(0.0);
  windowed.wall_heading_window_deg = 5.0;
  const LookAlikeGuard every(matcher, withAmbiguityMargin(0.0)), narrow(matcher, windowed);
  const auto scan = scanAtTruth(room, 1);
  const auto full = every.lookAlike(*scan, kTwin);
  const long long full_nodes = matcher->lastNodesScored();
  const auto found = narrow.lookAlike(*scan, kTwin);
  ASSERT_TRUE(full.has_value());
  ASSERT_TRUE(found.has_value());
  EXPECT_DOUBLE_EQ(found->pose.x, full->pose.x);
  EXPECT_DOUBLE_EQ(found->pose.y, full->pose.y);
  EXPECT_DOUBLE_EQ(found->score, full->score);
  EXPECT_LT(matcher->lastNodesScored(), full_nodes / 2);
  LookAlikeGuardParams bad;
  bad.wall_heading_window_deg = -1.0;
  EXPECT_THROW(LookAlikeGuard(matcher, bad), std::invalid_argument);
}

TEST(LookAlikeGuard, RefusesMarginsThatContradictEachOther) {
  const auto matcher = std::make_shared<CorrelativeMatcher>(test::asymmetricRoom());
  LookAlikeGuardParams p;
  p.score_margin = 0.1;
  p.ambiguity_margin = 0.05;
  EXPECT_THROW(LookAlikeGuard(matcher, p), std::invalid_argument);
  p.ambiguity_margin = 1.5;
  EXPECT_THROW(LookAlikeGuard(matcher, p), std::invalid_argument);
}

TEST(LookAlikeGuard, WidenedCovarianceCoversBothPlaces) {
  mrpt::math::CMatrixDouble33 cov;
  cov.setZero();
  cov(0, 0) = cov(1, 1) = 0.01;
  cov(2, 2) = 0.001;
  const auto wide = covarianceWithLookAlike(cov, {1.0, 1.0, 0.0}, {3.0, 1.0, 0.0});
  EXPECT_NEAR(wide(0, 0), 0.01 + 0.5 * 4.0, 1e-12) << "half the squared 2 m offset along x";
  EXPECT_NEAR(wide(1, 1), 0.01, 1e-12);
  EXPECT_NEAR(wide(0, 1), 0.0, 1e-12);
  EXPECT_FALSE(isConcentrated(filterSpread(wide), {}));
  const auto turned = covarianceWithLookAlike(cov, {0.0, 0.0, 3.1}, {0.0, 0.0, -3.1});
  EXPECT_NEAR(turned(2, 2), 0.001 + 0.5 * std::pow(2.0 * M_PI - 6.2, 2), 1e-9) << "the short way round";
}

/// Puts every particle tightly on one pose: a filter that has converged there.
class OnePoseInitializer : public ParticleInitializer {
 public:
  explicit OnePoseInitializer(mrpt::math::TPose2D pose) : pose_(pose) {}
  std::string name() const override { return "one-pose"; }
  void initialize(mrpt::slam::CMonteCarloLocalization2D& pf, mrpt::bayes::CParticleFilter::TParticleFilterOptions& o,
                  const mrpt::maps::COccupancyGridMap2D&, const mrpt::obs::CSensoryFrame&) override {
    o.adaptiveSampleSize = false;
    Rng rng(3);
    pf.m_particles.assign(400, {});
    for (auto& p : pf.m_particles) {
      p.d = mrpt::math::TPose2D(rng.normal(pose_.x, 0.05), rng.normal(pose_.y, 0.05), rng.normal(pose_.phi, 0.02));
      p.log_w = 0.0;
    }
  }

 private:
  mrpt::math::TPose2D pose_;
};

// A filter that converged on the twin stays there without the guard (its scan fit is high
// enough); with it, the first update moves half the particles to the truth and the next
// scans settle there.
TEST(LookAlikeGuard, MovesAFilterCollapsedOnTheTwinToTheTruth) {
  const auto room = std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  auto run = [&](bool guarded) {
    MclLocalizer loc(room, std::make_shared<OnePoseInitializer>(kTwin));
    if (guarded) loc.setLookAlikeGuard(std::make_shared<LookAlikeGuard>(std::make_shared<CorrelativeMatcher>(*room)));
    MclEstimate e;
    int found = 0;
    for (uint64_t i = 0; i < 6; ++i) {
      e = loc.update(stepWithScan(scanAtTruth(*room, 10 + i)));
      found += e.look_alike_found;
    }
    return std::make_pair(e, found);
  };
  const auto [unguarded, none] = run(false);
  EXPECT_EQ(none, 0);
  EXPECT_LT(distance(unguarded.mean, kTwin), 0.5) << "without the guard the filter stays on the twin";
  const auto [guarded, found] = run(true);
  EXPECT_EQ(found, 1) << "one convergence, one check that moved particles";
  EXPECT_LT(distance(guarded.mean, kTruth), 0.2);
  EXPECT_LT(std::sqrt(guarded.cov(0, 0)), 0.5) << "and it converged there";
}

// A filter that is right, in a room whose twin pose fits its scans nearly as well (with an
// ambiguity margin wider than the twin's shortfall). While the scans have not told the two apart
// it reports the twin and a covariance that covers both, without moving a particle; once they
// have, it claims the pose. With a zero margin the twin never counts.
TEST(LookAlikeGuard, ReportsARightFilterAsAmbiguousUntilTheScansTellTheTwinApart) {
  const auto room = std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  auto run = [&](LookAlikeGuardParams params, int* ambiguous_updates) {
    MclLocalizer loc(room, std::make_shared<OnePoseInitializer>(kTruth));
    loc.setLookAlikeGuard(std::make_shared<LookAlikeGuard>(std::make_shared<CorrelativeMatcher>(*room), params));
    MclEstimate e;
    *ambiguous_updates = 0;
    for (uint64_t i = 0; i < 3; ++i) {
      e = loc.update(stepWithScan(scanAtTruth(*room, 20 + i)));
      EXPECT_FALSE(e.look_alike_found) << "the twin fits worse: no particle moves";
      *ambiguous_updates += e.ambiguous_with.has_value();
    }
    return e;
  };
  auto undecided = withAmbiguityMargin(kTwinShortfallBound);
  undecided.rival_test.decisive_log_ratio = 1e9;  // more evidence than three scans can give
  int ambiguous = 0;
  const auto waiting = run(undecided, &ambiguous);
  EXPECT_EQ(ambiguous, 3);
  ASSERT_TRUE(waiting.ambiguous_with.has_value());
  EXPECT_LT(distance(*waiting.ambiguous_with, kTwin), 0.3);
  EXPECT_LT(distance(waiting.mean, kTruth), 0.1) << "the mean stays on the truth";
  EXPECT_FALSE(isConcentrated(filterSpread(waiting.cov), {}));

  const auto decided = run(withAmbiguityMargin(kTwinShortfallBound), &ambiguous);
  EXPECT_LT(ambiguous, 3);
  EXPECT_FALSE(decided.ambiguous_with.has_value()) << "the scans decided against the twin";
  EXPECT_TRUE(isConcentrated(filterSpread(decided.cov), {}));

  const auto strict = run(withAmbiguityMargin(0.0), &ambiguous);
  EXPECT_EQ(ambiguous, 0);
  EXPECT_TRUE(isConcentrated(filterSpread(strict.cov), {}));
}

/// One krp-bench trial, rebuilt from its seeds (trials.csv: trial_seed, filter_seed) as the bench
/// runs it, so a method can be replayed on it with other settings.
struct BenchTrialReplay {
  BenchTrialReplay(const std::string& name, uint64_t trial_seed, uint64_t filter_seed, int steps_after_first_scan)
      : world_name(name),
        world(readWorld(std::string(KRP_SOURCE_DIR) + "/sim_worlds/" + name + "/" + name + ".world.yaml")),
        map(loadOccupancyMap(world.map_path).grid) {
    TrialParams trial_params;
    trial_params.steps = steps_after_first_scan;
    trial_params.clutter = world.clutter;
    trial = generateTrial(*map, world.lidar(world.default_lidar_profile), trial_params, trial_seed);
    steps = trialToSteps(trial);
    filter_params.seed = static_cast<uint32_t>(filter_seed);
    filter_map = prepareSensorModelMap(*map, filter_params.sensor);
    settings.seeded.seed = filter_seed;
  }
  /// `seeded` with the world's shipped models and `settings`, the guard on, over every step.
  MclEstimate runSeeded(const MclParams& params) {
    if (!resources.relocalizers.count("seeded"))
      resources.relocalizers["seeded"] = std::make_shared<Relocalizer>(
          std::string(KRP_SOURCE_DIR) + "/models/" + world_name, *map, relocalizerParamsFor("seeded", settings.relocalizer),
          readZonesYaml(world.zones_path));
    MclLocalizer loc(filter_map, makeInitializer("seeded", settings, resources), params);
    loc.setLookAlikeGuard(makeLookAlikeGuard(*map, settings));
    MclEstimate e;
    for (const auto& step : steps) e = loc.update(step);
    return e;
  }
  std::string world_name;
  World world;
  std::shared_ptr<mrpt::maps::COccupancyGridMap2D> map;
  Trial trial;
  std::vector<RawlogStep> steps;
  MclParams filter_params;
  SensorModelMap filter_map;
  MethodSettings settings;
  MethodResources resources;
};

// krp-bench's corridor trial 20 of the degenerate scenes (scripts/bench_degenerate.sh, base
// seed 1), replayed as the bench runs it with `global-matcher-guarded`. The filter settles 7.6 m
// along the corridor from the robot, where many places fit the scans nearly as well. With one
// search per update, the look-alike under test lost at the last update and the estimate was
// reported unambiguous: confidently wrong. Searching again at once finds the next look-alike.
TEST(LookAlikeGuard, AWrongPoseInACorridorIsNotReportedUnambiguous) {
  BenchTrialReplay r("corridor", 1216750802008901446ull, 16078727496238170605ull, 10);
  // The fault shows with the likelihood field alone (the see-through penalty also prevents it).
  r.filter_params.see_through.enabled = false;
  auto& settings = r.settings;
  MethodResources resources;
  resources.matcher = std::make_shared<MatcherRelocalizer>(*r.map, settings.matcher);
  auto confidentlyWrongAtTheEnd = [&](int searches_per_update) {
    settings.guard.searches_per_update = searches_per_update;
    MclLocalizer loc(r.filter_map, makeInitializer("global-matcher-guarded", settings, resources), r.filter_params);
    loc.setLookAlikeGuard(makeLookAlikeGuard(*r.map, settings));
    MclEstimate e;
    for (const auto& step : r.steps) e = loc.update(step);
    return distance(e.mean, r.trial.truth.back()) > 1.0 && isConcentrated(filterSpread(e.cov), {});
  };
  EXPECT_TRUE(confidentlyWrongAtTheEnd(1)) << "the trial shows the fault with a single search per update";
  EXPECT_FALSE(confidentlyWrongAtTheEnd(LookAlikeGuardParams{}.searches_per_update));
}

// krp-bench's office trial 81 (scripts/bench_relocalization.sh office, base seed 1), replayed with
// `seeded` over 30 steps. The first scan's best answer is the 180 deg twin 8.4 m away, which
// explains the cluttered scan better than the truth; the truth, found as a look-alike, loses its
// test within three scans. Only metres later do the scans favour it. A rejected look-alike that
// is only left out of searches is never weighed again: the filter ends confidently wrong. Watched,
// it turns the estimate ambiguous once the scans have undone its defeat, and wins.
TEST(LookAlikeGuard, ALookAlikeDecidedAgainstTooEarlyIsWatchedAndComesBack) {
  BenchTrialReplay r("office_two_zone", 4072543816566992097ull, 18210581210280946496ull, 30);
  // The fault shows with the likelihood field alone (the see-through penalty also prevents it).
  r.filter_params.see_through.enabled = false;
  auto& settings = r.settings;
  MethodResources resources;
  resources.relocalizers["seeded"] =
      std::make_shared<Relocalizer>(std::string(KRP_SOURCE_DIR) + "/models/office_two_zone", *r.map,
                                    relocalizerParamsFor("seeded", settings.relocalizer), readZonesYaml(r.world.zones_path));
  auto run = [&](bool watch_rejected, int* ambiguous_updates) {
    settings.guard.watch_rejected = watch_rejected;
    MclLocalizer loc(r.filter_map, makeInitializer("seeded", settings, resources), r.filter_params);
    loc.setLookAlikeGuard(makeLookAlikeGuard(*r.map, settings));
    MclEstimate e;
    *ambiguous_updates = 0;
    for (const auto& step : r.steps) {
      e = loc.update(step);
      *ambiguous_updates += e.ambiguous_with.has_value();
    }
    return e;
  };
  int ambiguous_forgotten = 0, ambiguous_watched = 0;
  const auto forgotten = run(false, &ambiguous_forgotten);
  // The first scan is borderline: in the clang sanitizer build the relocalizer's best is the
  // truth itself and there is no fault to repair. The compiler the bench runs with shows it.
  if (distance(forgotten.mean, r.trial.truth.back()) < 0.5)
    GTEST_SKIP() << "this build seeds the truth on trial 81's first scan: the fault does not occur";
  EXPECT_GT(distance(forgotten.mean, r.trial.truth.back()), 3.0) << "the trial shows the fault without watching";
  EXPECT_TRUE(isConcentrated(filterSpread(forgotten.cov), {}));
  const auto watched = run(true, &ambiguous_watched);
  EXPECT_GT(ambiguous_watched, ambiguous_forgotten) << "the rejected twin was weighed again";
  EXPECT_FALSE(distance(watched.mean, r.trial.truth.back()) > 0.5 && isConcentrated(filterSpread(watched.cov), {}))
      << "not confidently wrong at the end";
}

// krp-bench's office trial 97 on base seed 5 (scripts/bench_fresh_seeds.sh), replayed with
// `seeded`. The first scan's best answer is right, but the particles collapse onto the look-alike
// room 12.9 m west at the first update: with the unmapped clutter, the likelihood field favours
// it scan after scan (by about 10 nats), so the guard's test keeps deciding against the truth.
// There, beams that went through the true room's doorways end on walls beyond the wall the map
// puts in their way. Charging them (SeeThroughPenalty) keeps the particles on the truth.
TEST(LookAlikeGuard, ALookAlikeRoomIsToldApartByTheBeamsItWouldHaveSeenThrough) {
  BenchTrialReplay r("office_two_zone", 3294957737319390126ull, 8881095260733888093ull, 10);
  auto run = [&](bool see_through) {
    MclParams params = r.filter_params;
    params.see_through.enabled = see_through;
    return r.runSeeded(params);
  };
  const auto field_only = run(false);
  if (distance(field_only.mean, r.trial.truth.back()) < 0.5)
    GTEST_SKIP() << "this build's filter stays on the truth with the likelihood field alone: the fault does not occur";
  EXPECT_GT(distance(field_only.mean, r.trial.truth.back()), 10.0) << "the trial shows the fault without the penalty";
  EXPECT_TRUE(isConcentrated(filterSpread(field_only.cov), {})) << "... and is confident";
  const auto charged = run(true);
  EXPECT_LT(distance(charged.mean, r.trial.truth.back()), 0.1);
}

// krp-bench's warehouse trial 21 (scripts/bench_relocalization.sh warehouse, seed 1), replayed
// as the bench runs `seeded`. The particles settle in an aisle that repeats the robot's, turned
// 180 deg and 10 m away. Scored by their endpoints alone, the places the guard's search finds
// fit better than the tracked pose only because their beams pass through racks, so each loses
// at once and the estimate was reported unambiguous: confidently wrong. Charging the search
// what each place sees through keeps such places from hiding the look-alikes that remain.
TEST(LookAlikeGuard, ASearchChargedForSeeThroughKeepsARepeatedAisleFromPassingAsTheRobotsPlace) {
  BenchTrialReplay r("warehouse", 1501835286251455644ull, 1153732462148343806ull, 10);
  auto run = [&](bool charged_search) {
    r.settings.guard.search_charges_see_through = charged_search;
    return r.runSeeded(r.filter_params);
  };
  const auto endpoints_only = run(false);
  const bool confident = isConcentrated(filterSpread(endpoints_only.cov), {});
  if (!confident || distance(endpoints_only.mean, r.trial.truth.back()) < 0.5)
    GTEST_SKIP() << "this build's filter is not confidently wrong here without the charge: the fault does not occur";
  EXPECT_GT(distance(endpoints_only.mean, r.trial.truth.back()), 5.0);
  const auto charged = run(true);
  const bool right = distance(charged.mean, r.trial.truth.back()) < 0.5;
  EXPECT_TRUE(right || !isConcentrated(filterSpread(charged.cov), {}))
      << "confidently wrong again, " << distance(charged.mean, r.trial.truth.back()) << " m from the robot";
}

// A watched look-alike comes back only as what the search would report: after a kidnap the
// tracked pose fits nothing, and a place that fits as little is no look-alike of it.
TEST(LookAlikeGuard, APlaceIsALookAlikeOnlyWhenTheMatcherWouldReportIt) {
  const auto room = test::asymmetricRoom();
  const LookAlikeGuard guard(std::make_shared<CorrelativeMatcher>(room), withAmbiguityMargin(kTwinShortfallBound));
  const auto scan = scanAtTruth(room, 3);
  EXPECT_TRUE(guard.isLookAlike(*scan, kTwin, kTruth));
  EXPECT_TRUE(guard.isLookAlike(*scan, kTruth, kTwin)) << "a better place is a look-alike too";
  // Two poses turned away from the scan's walls: both fit badly, within the margin of each other.
  const mrpt::math::TPose2D lost_a(kTruth.x, kTruth.y, mrpt::math::wrapToPi(kTruth.phi + 2.0));
  const mrpt::math::TPose2D lost_b(kTwin.x, kTwin.y, mrpt::math::wrapToPi(kTwin.phi + 2.0));
  const CorrelativeMatcher matcher(room);
  ASSERT_LT(matcher.scoreAt(*scan, lost_a), matcher.params().min_score);
  ASSERT_LT(std::abs(matcher.scoreAt(*scan, lost_a) - matcher.scoreAt(*scan, lost_b)), kTwinShortfallBound);
  EXPECT_FALSE(guard.isLookAlike(*scan, lost_b, lost_a));
}

TEST(LookAlikeGuard, RefusesAReopenLevelAtOrAboveTheDecisiveRatio) {
  LookAlikeGuardParams p;
  p.reopen_log_ratio = p.rival_test.decisive_log_ratio;
  EXPECT_THROW(LookAlikeGuard(std::make_shared<CorrelativeMatcher>(test::asymmetricRoom()), p), std::invalid_argument);
}

// A filter that is right, on scans whose returns mostly hit pillars the map does not hold: the
// particles stay tight, yet the scan cannot vouch for the pose. The guard reports it unsettled
// (widened covariance) below its fit floor, and not on clean scans or with the floor off.
TEST(LookAlikeGuard, ReportsAPoseTheScanMostlyFailsToExplainAsUnsettled) {
  const auto room = std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  const auto cluttered = test::asymmetricRoomWithPillarsAround(kTruth.x, kTruth.y, 6, 1.0, 0.4);
  auto lastEstimate = [&](double min_fit_fraction, const mrpt::maps::COccupancyGridMap2D& scanned) {
    auto params = withAmbiguityMargin(0.0);  // the twin plays no part here
    params.min_fit_fraction = min_fit_fraction;
    MclLocalizer loc(room, std::make_shared<OnePoseInitializer>(kTruth));
    loc.setLookAlikeGuard(std::make_shared<LookAlikeGuard>(std::make_shared<CorrelativeMatcher>(*room), params));
    MclEstimate e;
    for (uint64_t i = 0; i < 3; ++i) {
      e = loc.update(stepWithScan(scanAtTruth(scanned, 30 + i)));
    }
    return e;
  };
  const double floor = LookAlikeGuardParams{}.min_fit_fraction;
  const auto blocked = lastEstimate(floor, cluttered);
  EXPECT_LT(distance(blocked.mean, kTruth), 0.2) << "the particles stay on the truth";
  EXPECT_LT(blocked.fit_fraction, floor);
  EXPECT_GE(blocked.fit_fraction, 0.0);
  EXPECT_TRUE(blocked.scan_unexplained);
  EXPECT_FALSE(isConcentrated(filterSpread(blocked.cov), {}));

  const auto unguarded = lastEstimate(0.0, cluttered);
  EXPECT_FALSE(unguarded.scan_unexplained);
  EXPECT_TRUE(isConcentrated(filterSpread(unguarded.cov), {})) << "without the floor the same filter reads confident";

  const auto clean = lastEstimate(floor, *room);
  EXPECT_GT(clean.fit_fraction, 0.9);
  EXPECT_FALSE(clean.scan_unexplained);
  EXPECT_TRUE(isConcentrated(filterSpread(clean.cov), {}));
}

TEST(LookAlikeGuard, RefusesAFitFloorOutsideZeroToOneOrASpreadThatReadsConverged) {
  const auto matcher = std::make_shared<CorrelativeMatcher>(test::asymmetricRoom());
  LookAlikeGuardParams p;
  p.min_fit_fraction = 1.2;
  EXPECT_THROW(LookAlikeGuard(matcher, p), std::invalid_argument);
  p.min_fit_fraction = std::nan("");
  EXPECT_THROW(LookAlikeGuard(matcher, p), std::invalid_argument);
  p = {};
  p.unexplained_xy_std_m = 0.1;
  p.unexplained_phi_std_deg = 2.0;
  EXPECT_THROW(LookAlikeGuard(matcher, p), std::invalid_argument);
}

TEST(LookAlikeGuard, RefusesANegativeHistory) {
  LookAlikeGuardParams p;
  p.history_updates = -1;
  EXPECT_THROW(LookAlikeGuard(std::make_shared<CorrelativeMatcher>(test::asymmetricRoom()), p), std::invalid_argument);
  p.history_updates = 0;
  EXPECT_NO_THROW(LookAlikeGuard(std::make_shared<CorrelativeMatcher>(test::asymmetricRoom()), p));
}

/// The guard refuses `field` just below 0 and just above `largest`, and accepts `largest`.
template <typename T>
void expectRefusedOutsideZeroTo(T LookAlikeGuardParams::*field, T largest) {
  const auto matcher = std::make_shared<CorrelativeMatcher>(test::asymmetricRoom());
  LookAlikeGuardParams p;
  p.*field = -1;
  EXPECT_THROW(LookAlikeGuard(matcher, p), std::invalid_argument);
  p.*field = largest + 1;
  EXPECT_THROW(LookAlikeGuard(matcher, p), std::invalid_argument);
  p.*field = largest;
  EXPECT_NO_THROW(LookAlikeGuard(matcher, p));
}

TEST(LookAlikeGuard, RefusesARecheckIntervalOutsideItsRange) {
  expectRefusedOutsideZeroTo(&LookAlikeGuardParams::recheck_every_updates, LookAlikeGuardParams::kMaxRecheckEveryUpdates);
}

TEST(LookAlikeGuard, RefusesNoSearchPerUpdate) {
  LookAlikeGuardParams p;
  p.searches_per_update = 0;
  EXPECT_THROW(LookAlikeGuard(std::make_shared<CorrelativeMatcher>(test::asymmetricRoom()), p), std::invalid_argument);
}

// A right filter with no look-alike within the margin: the guard searches at the fresh
// convergence and then every recheck_every_updates updates (0: never again), and each update
// reports the searches it ran and their CPU, which is part of the update's.
TEST(LookAlikeGuard, SearchesAsOftenAsTheRecheckIntervalSaysAndReportsTheirCost) {
  const auto room = std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  const auto matcher = std::make_shared<CorrelativeMatcher>(*room);
  auto searches = [&](int recheck_every) {
    auto params = withAmbiguityMargin(0.0);
    params.recheck_every_updates = recheck_every;
    MclLocalizer loc(room, std::make_shared<OnePoseInitializer>(kTruth));
    loc.setLookAlikeGuard(std::make_shared<LookAlikeGuard>(matcher, params));
    std::vector<int> per_update;
    for (uint64_t i = 0; i < 7; ++i) {
      const auto e = loc.update(stepWithScan(scanAtTruth(*room, 40 + i)));
      per_update.push_back(e.look_alike_searches);
      EXPECT_GE(e.look_alike_search_cpu_s, 0.0);
      EXPECT_LE(e.look_alike_search_cpu_s, e.cpu_s);
      if (e.look_alike_searches == 0) {
        EXPECT_EQ(e.look_alike_search_cpu_s, 0.0);
      } else {
        EXPECT_GT(e.look_alike_search_cpu_s, 0.0);
      }
    }
    return per_update;
  };
  EXPECT_EQ(searches(1), (std::vector<int>{1, 1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(searches(3), (std::vector<int>{1, 0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(searches(0), (std::vector<int>{1, 0, 0, 0, 0, 0, 0}));
  // Without a guard nothing is searched.
  MclLocalizer unguarded(room, std::make_shared<OnePoseInitializer>(kTruth));
  EXPECT_EQ(unguarded.update(stepWithScan(scanAtTruth(*room, 40))).look_alike_searches, 0);
}

// A search that runs out of its node budget with nothing found has not ruled out a look-alike:
// until one search since the filter converged finishes, the estimate is reported unverified and
// its spread widened like an unexplained scan's; the switch leaves only the flag.
TEST(LookAlikeGuard, AConvergenceNoSearchCouldFinishCheckingIsReportedUnverified) {
  const auto room = std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  const auto matcher = std::make_shared<CorrelativeMatcher>(*room);
  auto guardWithBudget = [&](long long nodes, bool unverified_is_unsettled = true) {
    auto params = withAmbiguityMargin(0.0);
    params.max_search_nodes = nodes;
    params.unverified_is_unsettled = unverified_is_unsettled;
    return std::make_shared<LookAlikeGuard>(matcher, params);
  };
  constexpr long long kNoLimit = 0, kOneNode = 1;
  const double settled_xy_std_m = LookAlikeGuardParams{}.converged.xy_std_m;
  const double widened_xy_std_m = LookAlikeGuardParams{}.unexplained_xy_std_m;

  MclLocalizer starved(room, std::make_shared<OnePoseInitializer>(kTruth));
  starved.setLookAlikeGuard(guardWithBudget(kOneNode));
  for (uint64_t i = 0; i < 4; ++i) {
    const auto e = starved.update(stepWithScan(scanAtTruth(*room, 60 + i)));
    EXPECT_EQ(e.look_alike_searches, 1);
    EXPECT_EQ(e.look_alike_searches_unfinished, 1);
    EXPECT_TRUE(e.look_alike_unverified) << "update " << i;
    EXPECT_GE(std::sqrt(e.cov(0, 0)) + 1e-9, widened_xy_std_m) << "update " << i;
  }

  MclLocalizer flagged_only(room, std::make_shared<OnePoseInitializer>(kTruth));
  flagged_only.setLookAlikeGuard(guardWithBudget(kOneNode, false));
  const auto flagged = flagged_only.update(stepWithScan(scanAtTruth(*room, 60)));
  EXPECT_TRUE(flagged.look_alike_unverified);
  EXPECT_LT(std::sqrt(flagged.cov(0, 0)), settled_xy_std_m) << "the switch off leaves the spread as it is";

  // One finished search verifies the convergence: later searches out of budget do not undo it.
  MclLocalizer checked(room, std::make_shared<OnePoseInitializer>(kTruth));
  checked.setLookAlikeGuard(guardWithBudget(kNoLimit));
  for (uint64_t i = 0; i < 2; ++i) {
    const auto e = checked.update(stepWithScan(scanAtTruth(*room, 70 + i)));
    EXPECT_EQ(e.look_alike_searches_unfinished, 0);
    EXPECT_FALSE(e.look_alike_unverified);
  }
  checked.setLookAlikeGuard(guardWithBudget(kOneNode));
  const auto after = checked.update(stepWithScan(scanAtTruth(*room, 72)));
  EXPECT_EQ(after.look_alike_searches_unfinished, 1);
  EXPECT_FALSE(after.look_alike_unverified);
  EXPECT_LT(std::sqrt(after.cov(0, 0)), settled_xy_std_m);
}

TEST(LookAlikeGuard, RefusesASearchBudgetOutsideItsRange) {
  expectRefusedOutsideZeroTo(&LookAlikeGuardParams::max_search_nodes, LookAlikeGuardParams::kMaxSearchNodesLimit);
}

TEST(LookAlikeGuard, RefusesAPerUpdateBudgetOutsideItsRange) {
  expectRefusedOutsideZeroTo(&LookAlikeGuardParams::max_nodes_per_update, LookAlikeGuardParams::kMaxSearchNodesLimit);
}

// A search set up to run in slices owns its scan's see-through charge (the scan's may be gone
// by the next slice) and ends with what one search run at once finds.
TEST(LookAlikeGuard, ASearchInSlicesFindsWhatOneSearchFinds) {
  const auto room = std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  const LookAlikeGuard guard(std::make_shared<CorrelativeMatcher>(*room), withAmbiguityMargin(0.0));
  const SeeThroughPenalty penalty(*room, SensorModelParams{});
  const auto scan = scanAtTruth(*room, 1);
  std::unique_ptr<LookAlikeSearchInProgress> sliced;
  LookAlikeSearch whole;
  {
    const auto see_through = penalty.forScan(*scan);
    whole = guard.search(*scan, kTwin, {}, &see_through);
    sliced = guard.startSearch(*scan, kTwin, {}, &see_through);
  }
  ASSERT_TRUE(whole.found.has_value());
  EXPECT_LT(distance(whole.found->pose, kTruth), 0.2);
  int paused = 0;
  LookAlikeSearch last;
  while ((last = guard.resume(*sliced, 200)).paused) ++paused;
  EXPECT_GE(paused, 2) << "a budget of 200 nodes a slice should pause the search";
  ASSERT_TRUE(last.found.has_value());
  EXPECT_EQ(last.found->pose.x, whole.found->pose.x);
  EXPECT_EQ(last.found->pose.y, whole.found->pose.y);
  EXPECT_EQ(last.found->pose.phi, whole.found->pose.phi);
  EXPECT_EQ(last.found->score, whole.found->score);
  EXPECT_EQ(last.found->tracked_score, whole.found->tracked_score);
  EXPECT_EQ(last.cut_short, whole.cut_short);
}

/// A filter step holding `scan` and the odometry `increment` since the last step.
RawlogStep stepWithScanAndMotion(mrpt::obs::CObservation2DRangeScan::Ptr scan, const mrpt::poses::CPose2D& increment) {
  auto step = stepWithScan(std::move(scan));
  step.action = mrpt::obs::CActionCollection::Create();
  mrpt::obs::CActionRobotMovement2D move;
  move.computeFromOdometry(increment, OdometryModelParams{}.toMrpt());
  step.action->insert(move);
  return step;
}

// The guard's search spread over updates (max_nodes_per_update): while it runs, the estimate
// reads unverified; when it ends, the place it found for the scan it started on is moved along
// the odometry since, so that the look-alike reported is the twin of where the robot is now,
// not of where it was. The same filter with whole searches reports that twin at once.
TEST(LookAlikeGuard, ASearchSpreadOverUpdatesReportsTheLookAlikeOfWhereTheRobotIsNow) {
  const auto room = std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  const auto matcher = std::make_shared<CorrelativeMatcher>(*room);
  const auto twinOf = [](const mrpt::math::TPose2D& p) {
    return mrpt::math::TPose2D(9.0 - p.x, 7.0 - p.y, mrpt::math::wrapToPi(p.phi + M_PI));
  };
  const mrpt::poses::CPose2D step_forward(0.25, 0.0, 0.0);
  auto run = [&](long long nodes_per_update, std::vector<MclEstimate>* estimates) {
    auto params = withAmbiguityMargin(kTwinShortfallBound);
    params.rival_test.decisive_log_ratio = 1e9;  // the twin stays undecided: reported every update
    params.max_nodes_per_update = nodes_per_update;
    MclLocalizer loc(room, std::make_shared<OnePoseInitializer>(kTruth));
    loc.setLookAlikeGuard(std::make_shared<LookAlikeGuard>(matcher, params));
    mrpt::poses::CPose2D truth(kTruth);
    std::vector<mrpt::math::TPose2D> path;
    for (uint64_t i = 0; i < 8; ++i) {
      const mrpt::poses::CPose2D increment = i == 0 ? mrpt::poses::CPose2D() : step_forward;
      truth = truth + increment;
      path.push_back(truth.asTPose());
      Rng rng(80 + i);
      const auto scan = ScanSimulator(lidarProfileByName("omni_12m")).simulate(*room, truth, rng);
      estimates->push_back(loc.update(stepWithScanAndMotion(scan, increment)));
    }
    return path;
  };
  std::vector<MclEstimate> whole;
  const auto path = run(0, &whole);
  ASSERT_TRUE(whole.front().ambiguous_with.has_value()) << "a whole search reports the twin at once";
  EXPECT_LT(distance(*whole.front().ambiguous_with, twinOf(path.front())), 0.3);
  EXPECT_FALSE(whole.front().look_alike_search_pending);

  // A few thousand nodes an update: the search of the first scan (some 17,000) takes several.
  std::vector<MclEstimate> sliced;
  run(4000, &sliced);
  size_t reported = sliced.size();
  for (size_t i = 0; i < sliced.size(); ++i)
    if (sliced[i].ambiguous_with) {
      reported = i;
      break;
    }
  ASSERT_LT(reported, sliced.size()) << "the search should end within the run";
  ASSERT_GE(reported, 2u) << "the search should have paused at least twice";
  for (size_t i = 0; i < reported; ++i) {
    EXPECT_TRUE(sliced[i].look_alike_search_pending) << "update " << i;
    EXPECT_TRUE(sliced[i].look_alike_unverified) << "update " << i;
    EXPECT_FALSE(isConcentrated(filterSpread(sliced[i].cov), {})) << "unverified reads unsettled, update " << i;
  }
  EXPECT_FALSE(sliced[reported].look_alike_search_pending);
  const auto& place = *sliced[reported].ambiguous_with;
  EXPECT_LT(distance(place, twinOf(path[reported])), 0.3) << "the twin of where the robot is now";
  EXPECT_GT(distance(twinOf(path.front()), twinOf(path[reported])), 0.7) << "the robot moved well away meanwhile";
}

// Spread over updates, the search that follows a look-alike which just lost its test is looking
// for the next one: while it runs, the pose reads unverified even though the search that found
// the loser finished (a whole search would have answered in that update). Without this rule a
// warehouse trial ended confidently wrong (reports/guard_budget).
TEST(LookAlikeGuard, WhileTheSearchForTheNextLookAlikeRunsThePoseIsUnverified) {
  const auto room = std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  auto params = withAmbiguityMargin(kTwinShortfallBound);  // the twin is a look-alike that loses at once
  params.max_nodes_per_update = 4000;                      // a search of this room takes several updates
  MclLocalizer loc(room, std::make_shared<OnePoseInitializer>(kTruth));
  loc.setLookAlikeGuard(std::make_shared<LookAlikeGuard>(std::make_shared<CorrelativeMatcher>(*room), params));
  int checked = 0, verified = 0;
  for (uint64_t i = 0; i < 12; ++i) {
    const auto e = loc.update(stepWithScan(scanAtTruth(*room, 90 + i)));
    verified += !e.look_alike_unverified;
    // Two searches in one update: the first ended (its look-alike lost at once), the next began.
    if (e.look_alike_searches >= 2 && e.look_alike_search_pending) {
      EXPECT_TRUE(e.look_alike_unverified) << "update " << i;
      EXPECT_FALSE(isConcentrated(filterSpread(e.cov), {})) << "update " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0) << "the twin should be found and lose at once within the run";
  EXPECT_GT(verified, 0) << "the search after it should end, and verify the pose, within the run";
}

}  // namespace
}  // namespace krp
