// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "mrpt_krp_plugin/bench/bench_report.h"
#include "mrpt_krp_plugin/bench/kidnap_report.h"
#include "mrpt_krp_plugin/bench/trial_metrics.h"
#include "mrpt_krp_plugin/filter/look_alike_guard.h"

namespace krp {
namespace {

UpdateRecord rec(double err_m, double err_deg, double std_m, size_t particles, double cpu, double dist) {
  UpdateRecord r;
  r.error_xy_m = err_m;
  r.error_phi_deg = err_deg;
  r.spread.xy_std_m = std_m;
  r.spread.phi_std_deg = 2.0;
  r.particles = particles;
  r.cpu_s = cpu;
  r.distance_m = dist;
  return r;
}

TEST(TrialMetrics, ConvergenceMustHoldAtEveryLaterUpdate) {
  // Within tolerance at update 2, out at 3, in from 4 on: converges at update 4.
  const std::vector<UpdateRecord> u = {rec(5, 90, 3, 1000, 1, 0), rec(0.2, 2, 0.1, 800, 1, 0.2), rec(2, 2, 0.1, 500, 1, 0.4),
                                       rec(0.1, 1, 0.05, 300, 1, 0.6), rec(0.05, 1, 0.05, 200, 1, 0.8)};
  const auto o = evaluateTrial(u, {});
  EXPECT_TRUE(o.converged);
  EXPECT_EQ(o.updates_to_convergence, 4);
  EXPECT_NEAR(o.distance_to_convergence_m, 0.6, 1e-12);
  EXPECT_NEAR(o.cpu_to_convergence_s, 4.0, 1e-12);
  EXPECT_NEAR(o.particle_updates_to_convergence, 1000 + 800 + 500 + 300, 1e-9);
  EXPECT_EQ(o.initial_particles, 1000u);
  EXPECT_NEAR(o.mean_particles, 560.0, 1e-9);
  EXPECT_FALSE(o.confident_but_wrong);
}

TEST(TrialMetrics, TheGuardsSearchesAddUpOverTheTrial) {
  std::vector<UpdateRecord> u = {rec(5, 90, 3, 1000, 0.1, 0), rec(0.1, 1, 0.05, 300, 0.2, 0.2),
                                 rec(0.05, 1, 0.05, 200, 0.3, 0.4)};
  u[1].look_alike_searches = 1;
  u[1].look_alike_search_cpu_s = 0.15;
  u[2].look_alike_searches = 3;
  u[2].look_alike_search_cpu_s = 0.25;
  const auto o = evaluateTrial(u, {});
  EXPECT_EQ(o.look_alike_searches, 4);
  EXPECT_NEAR(o.look_alike_search_cpu_s, 0.4, 1e-12);
  EXPECT_NEAR(o.total_cpu_s, 0.6, 1e-12);
}

TEST(TrialMetrics, ConfidentButWrongIsSmallSpreadWithWrongPose) {
  const auto wrong_tight = evaluateTrial({rec(5, 3, 3, 100, 1, 0), rec(12, 180, 0.1, 100, 1, 0.2)}, {});
  EXPECT_FALSE(wrong_tight.converged);
  EXPECT_EQ(wrong_tight.updates_to_convergence, -1);
  EXPECT_TRUE(wrong_tight.confident_but_wrong);
  EXPECT_FALSE(wrong_tight.confident_and_right);
  const auto wrong_wide = evaluateTrial({rec(12, 180, 4.0, 100, 1, 0)}, {});
  EXPECT_FALSE(wrong_wide.confident_but_wrong);
  const auto first_scan = evaluateTrial({rec(0.1, 1, 0.1, 100, 1, 0), rec(0.1, 1, 0.1, 100, 1, 0.2)}, {});
  EXPECT_EQ(first_scan.updates_to_convergence, 1);
  EXPECT_TRUE(first_scan.confident_and_right);
  EXPECT_FALSE(evaluateTrial({rec(0.1, 1, 0.9, 100, 1, 0)}, {}).confident_and_right) << "right but spread out";
  EXPECT_NEAR(first_scan.distance_to_convergence_m, 0.0, 1e-12);
}

TEST(TrialMetrics, HeadingToleranceCounts) {
  const auto o = evaluateTrial({rec(0.1, 25, 0.1, 100, 1, 0)}, {});
  EXPECT_FALSE(o.converged);
}

TEST(TrialMetrics, UpdateRecordFromEstimate) {
  MclEstimate e;
  e.mean = {1.0, 2.0, 0.1};
  e.cov.setZero();
  e.cov(0, 0) = 0.04;
  e.cov(1, 1) = 0.01;
  e.cov(2, 2) = std::pow(5.0 * M_PI / 180.0, 2);
  e.particles = 42;
  e.look_alike_searches = 2;
  e.look_alike_search_cpu_s = 0.03;
  const auto r = makeUpdateRecord(e, {1.3, 2.4, 0.1 + M_PI / 18}, 1.5);
  EXPECT_EQ(r.look_alike_searches, 2);
  EXPECT_EQ(r.look_alike_search_cpu_s, 0.03);
  EXPECT_NEAR(r.error_xy_m, 0.5, 1e-9);
  EXPECT_NEAR(r.error_phi_deg, 10.0, 1e-9);
  EXPECT_NEAR(r.spread.xy_std_m, 0.2, 1e-9);
  EXPECT_NEAR(r.spread.phi_std_deg, 5.0, 1e-9);
  EXPECT_EQ(r.particles, 42u);
}

TEST(TrialMetrics, KidnapDetectionAndRecoveryCountFromTheKidnap) {
  // Tracking (updates 0-2), carried before update 3: the old pose is 6 m off for three updates,
  // the detector fires at update 5, the re-initialized filter is right from update 7 on.
  std::vector<UpdateRecord> u = {rec(0.1, 1, 0.1, 500, 1, 0), rec(0.1, 1, 0.1, 500, 1, 0.2), rec(0.1, 1, 0.1, 500, 1, 0.4),
                                 rec(6, 1, 0.1, 500, 2, 0.4),  rec(6, 1, 0.1, 500, 2, 0.6),   rec(6, 1, 0.1, 500, 2, 0.8),
                                 rec(3, 40, 2.0, 5000, 4, 1.0), rec(0.1, 1, 0.1, 800, 3, 1.2), rec(0.1, 1, 0.1, 600, 1, 1.4)};
  u[5].kidnap_detected = true;
  const auto k = evaluateKidnap(u, 3, {});
  EXPECT_TRUE(k.tracking_before);
  EXPECT_EQ(k.updates_to_detect, 3);
  EXPECT_TRUE(k.recovered);
  EXPECT_EQ(k.updates_to_recover, 5);       // update 7 is the fifth after the kidnap
  EXPECT_DOUBLE_EQ(k.cpu_to_recover_s, 13.0);  // 2 + 2 + 2 + 4 + 3
  EXPECT_FALSE(k.confident_but_wrong);

  // Never detected: it stays confidently at the old place.
  u[5].kidnap_detected = false;
  for (size_t i = 6; i < u.size(); ++i) u[i] = rec(6, 1, 0.1, 500, 1, 1.0);
  const auto stuck = evaluateKidnap(u, 3, {});
  EXPECT_EQ(stuck.updates_to_detect, -1);
  EXPECT_FALSE(stuck.recovered);
  EXPECT_TRUE(stuck.confident_but_wrong);
  EXPECT_THROW(evaluateKidnap(u, 0, {}), std::invalid_argument);
  EXPECT_THROW(evaluateKidnap(u, u.size(), {}), std::invalid_argument);
}


TEST(BenchSummary, KidnapRatesAreOverTrialsThatWereTracking) {
  auto trial = [](bool tracking, int detect, bool recovered, int recover) {
    TrialRecord r;
    r.world = "w", r.lidar = "l", r.method = "m", r.kidnap_step = 5;
    r.kidnap.tracking_before = tracking;
    r.kidnap.updates_to_detect = detect;
    r.kidnap.recovered = recovered;
    r.kidnap.updates_to_recover = recover;
    r.kidnap.cpu_to_recover_s = 1.0;
    return r;
  };
  // A lost filter that "detects" does not count; one tracking trial recovers, one does not.
  const std::vector<TrialRecord> records = {trial(true, 3, true, 5), trial(true, -1, false, -1), trial(false, 1, true, 2)};
  const auto s = summarizeKidnaps(records);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].trials, 3);
  EXPECT_EQ(s[0].tracking_before, 2);
  EXPECT_DOUBLE_EQ(s[0].detected_rate, 0.5);
  EXPECT_DOUBLE_EQ(s[0].recovered_rate, 0.5);
  EXPECT_DOUBLE_EQ(s[0].median_updates_to_recover, 5.0);
  EXPECT_NE(kidnapSection(s, 5).find("| w | l | m | 3 | 2 (66.7 %) | 50 % | 3 | 50 % | 5 |"), std::string::npos)
      << kidnapSection(s, 5);
  EXPECT_TRUE(kidnapSection(summarizeKidnaps({}), 5).empty());
}

// The first-scan relocalization rates count only methods with a relocalizer, over their trials.
TEST(BenchSummary, RelocalizerRatesCountWhereTheBestCameFrom) {
  auto trial = [](const char* method, int hypotheses, bool localized, double error_m, bool from_matcher, double cpu_s) {
    TrialRecord r;
    r.world = "w", r.lidar = "l", r.method = method;
    r.seed_hypotheses = hypotheses;
    r.seed_localized = localized;
    r.seed_best_error_xy_m = error_m;
    r.seed_best_confidence = hypotheses > 0 ? 0.9 : -1.0;
    r.seed_best_from_matcher = from_matcher;
    r.seed_cpu_s = cpu_s;
    return r;
  };
  const std::vector<TrialRecord> records = {
      trial("seeded", 2, true, 0.1, true, 0.040), trial("seeded", 1, true, 3.0, false, 0.010),
      trial("seeded", 1, false, 0.2, false, 0.030), trial("seeded", 0, false, -1, false, 0.020),
      trial("uniform-mcl", -1, false, -1, false, -1.0)};
  const auto s = summarize(records, 0.5);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[0].seed_localized_rate, 0.5);
  EXPECT_DOUBLE_EQ(s[0].seed_best_right_rate, 0.5);
  EXPECT_DOUBLE_EQ(s[0].seed_localized_wrong_rate, 0.25);
  EXPECT_DOUBLE_EQ(s[0].seed_best_from_matcher_rate, 0.25);
  EXPECT_LT(s[1].seed_best_from_matcher_rate, 0.0) << "no relocalizer, no rate";
  EXPECT_DOUBLE_EQ(s[0].median_seed_cpu_s, 0.025);
  EXPECT_DOUBLE_EQ(s[0].p90_seed_cpu_s, 0.037) << "linear between the 3rd and 4th of 4";
  EXPECT_LT(s[1].median_seed_cpu_s, 0.0) << "no relocalizer, no time";
  const auto table = relocalizerTable(s, 0.5);
  EXPECT_NE(table.find("| w | l | seeded | 50 % | 50 % | 25 % | 25 % | 25 | 37 |"), std::string::npos) << table;
  EXPECT_EQ(table.find("uniform-mcl"), std::string::npos) << table;
}

// An estimate the guard reports as ambiguous is not confident however tight its particles are:
// the record reads the widened covariance the filter reports.
TEST(TrialMetrics, AnAmbiguousEstimateIsNotConfident) {
  MclEstimate e;
  e.mean = {1.0, 2.0, 0.0};
  e.cov.setZero();
  e.cov(0, 0) = e.cov(1, 1) = 0.01;
  e.cov(2, 2) = 0.001;
  const auto tight = makeUpdateRecord(e, e.mean, 0.0);
  EXPECT_FALSE(tight.ambiguous);
  EXPECT_TRUE(evaluateTrial({tight}, {}).confident_and_right);
  e.ambiguous_with = mrpt::math::TPose2D(4.0, 2.0, 0.0);
  e.cov = covarianceWithLookAlike(e.cov, e.mean, *e.ambiguous_with);
  const auto ambiguous = makeUpdateRecord(e, e.mean, 0.0);
  EXPECT_TRUE(ambiguous.ambiguous);
  const auto o = evaluateTrial({ambiguous}, {});
  EXPECT_TRUE(o.converged) << "right all the same";
  EXPECT_FALSE(o.confident_and_right);
  EXPECT_FALSE(o.confident_but_wrong);
}

TEST(BenchSummary, ConfidentRatesSplitRightFromWrong) {
  auto trial = [](bool confident, bool right) {
    TrialRecord r;
    r.world = "w", r.lidar = "l", r.method = "m";
    r.outcome.converged = right;
    r.outcome.confident_but_wrong = confident && !right;
    r.outcome.confident_and_right = confident && right;
    return r;
  };
  const auto s = summarize({trial(true, true), trial(true, true), trial(true, false), trial(false, true)}, 0.5);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_DOUBLE_EQ(s[0].success_rate, 0.75);
  EXPECT_DOUBLE_EQ(s[0].confident_wrong_rate, 0.25);
  EXPECT_DOUBLE_EQ(s[0].confident_right_rate, 0.5);
  const auto table = summaryTable(s);
  EXPECT_NE(table.find("| w | l | m | 4 | 75 % | 25 % | 50 % |"), std::string::npos) << table;
}

}  // namespace
}  // namespace krp
