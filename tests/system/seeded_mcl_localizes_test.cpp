// SPDX-License-Identifier: BSD-3-Clause
// System test: MCL seeded by hypotheses converges from the first scan with a few hundred
// particles where uniform MCL needs tens of thousands. The hypotheses come from a stand-in
// for the relocalizer (the truth perturbed, next to a wrong place), so this pins the seeding
// and the filter, not the models.
#include <gtest/gtest.h>

#include "mrpt_krp_plugin/bench/trial_metrics.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/filter_spread.h"
#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/filter/seeded_initializer.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "support/seeded_drives.h"
#include "support/test_maps.h"

namespace krp {
namespace {

using test::hypothesisAt;

TEST(SystemSeededMcl, ConvergesFromTheFirstScanWithFewParticles) {
  const auto room = std::make_shared<const mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  TrialParams tp;
  tp.steps = 5;
  SeededInitParams sp;
  sp.particles_per_hypothesis = 300;
  int converged_first = 0;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const Trial t = generateTrial(*room, lidarProfileByName("omni_12m"), tp, seed);
    const auto truth = t.truth[0];
    // 0.3 m and 5 deg off the truth, and an equally trusted hypothesis in the wrong place.
    const mrpt::math::TPose2D near_truth(truth.x + 0.3, truth.y - 0.2, truth.phi + 0.08);
    const mrpt::math::TPose2D elsewhere(truth.x > 4.5 ? 1.5 : 7.5, 5.5, truth.phi + 2.0);
    Ranking ranking;
    ranking.hypotheses = {hypothesisAt(near_truth, 0.5), hypothesisAt(elsewhere, 0.5)};
    sp.seed = seed;
    auto init = std::make_shared<SeededInitializer>([&](const auto&) { return ranking; }, sp);
    MclParams mp;
    mp.seed = static_cast<uint32_t>(seed);
    MclLocalizer loc(room, init, mp);
    const auto steps = trialToSteps(t);
    std::vector<UpdateRecord> u;
    for (size_t i = 0; i < steps.size(); ++i) u.push_back(makeUpdateRecord(loc.update(steps[i]), t.truth[i], t.distance_m[i]));
    EXPECT_LE(u.front().particles, 700u);
    const auto o = evaluateTrial(u, {});
    EXPECT_TRUE(o.converged) << "seed " << seed;
    EXPECT_LT(o.final_error_xy_m, 0.2) << "seed " << seed;
    converged_first += o.updates_to_convergence == 1 ? 1 : 0;
  }
  EXPECT_GE(converged_first, 4) << "the scan likelihood should pick the right hypothesis at the first update";
}

}  // namespace
}  // namespace krp

namespace krp {
namespace {

TEST(SystemSeededMcl, DetectsAKidnapAndRecoversByReseeding) {
  const auto room = std::make_shared<const mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  TrialParams tp;
  tp.steps = 12;
  const Trial before = generateTrial(*room, lidarProfileByName("omni_12m"), tp, 3);
  const Trial after = generateTrial(*room, lidarProfileByName("omni_12m"), tp, 4);  // carried elsewhere
  ASSERT_GT(std::hypot(before.truth.back().x - after.truth[0].x, before.truth.back().y - after.truth[0].y), 1.0);
  mrpt::math::TPose2D current;  // what a perfect relocalizer would answer for the current scan
  auto init = std::make_shared<SeededInitializer>([&](const auto&) {
    Ranking r;
    r.hypotheses = {hypothesisAt(current, 1.0)};
    return r;
  });
  MclParams mp;
  mp.kidnap.enabled = true;
  MclLocalizer loc(room, init, mp);
  const auto steps_before = trialToSteps(before), steps_after = trialToSteps(after);
  int initializations = 0, kidnap_at = -1, reinit_at = -1;
  for (size_t i = 0; i < steps_before.size(); ++i) {
    current = before.truth[i];
    const auto e = loc.update(steps_before[i]);
    initializations += e.initialized;
    EXPECT_FALSE(e.kidnap_detected) << "false alarm at update " << i << ", fit " << e.fit_fraction;
  }
  MclEstimate last;
  for (size_t i = 0; i < steps_after.size(); ++i) {
    current = after.truth[i];
    last = loc.update(steps_after[i]);
    if (last.kidnap_detected && kidnap_at < 0) kidnap_at = static_cast<int>(i);
    if (last.initialized && reinit_at < 0) reinit_at = static_cast<int>(i);
  }
  EXPECT_EQ(initializations, 1);
  ASSERT_GE(kidnap_at, 0) << "the kidnap went unnoticed";
  EXPECT_LE(kidnap_at, 4) << "three bad updates in a row should be enough";
  EXPECT_EQ(reinit_at, kidnap_at + 1);
  EXPECT_LT(std::hypot(last.mean.x - after.truth.back().x, last.mean.y - after.truth.back().y), 0.2);
}

}  // namespace
}  // namespace krp

namespace krp {
namespace {

// The shrinking tests' drive.
using test::RoomTrial;

// With nothing from the relocalizer the filter starts uniform, over the whole map; once it has
// converged it should track with a seeded start's few hundred particles, not keep them all.
TEST(SystemSeededMcl, AUniformStartShrinksOnceItConverges) {
  const RoomTrial rt;
  const auto run = [&](bool shrink) {
    SeededInitParams sp;
    sp.fallback.particles = 20000;
    if (!shrink) sp.fallback_shrinks.reset();
    auto init = std::make_shared<SeededInitializer>([](const auto&) { return Ranking{}; }, sp);
    MclLocalizer loc(rt.room, init, MclParams{});
    std::vector<UpdateRecord> u;
    for (size_t i = 0; i < rt.steps.size(); ++i)
      u.push_back(makeUpdateRecord(loc.update(rt.steps[i]), rt.trial.truth[i], rt.trial.distance_m[i]));
    EXPECT_TRUE(init->lastSeeding()->fell_back_to_uniform);
    EXPECT_EQ(init->lastSeeding()->particles, 20000u);
    return u;
  };
  const auto shrinking = run(true), fixed = run(false);
  EXPECT_EQ(shrinking.front().particles, 20000u) << "the first update weighs the whole start";
  EXPECT_TRUE(evaluateTrial(shrinking, {}).converged);
  EXPECT_LE(shrinking.back().particles, 1000u) << "converged in one room, yet kept its uniform start's count";
  EXPECT_GE(shrinking.back().particles, SeededInitParams{}.min_particles);
  EXPECT_TRUE(evaluateTrial(fixed, {}).converged);
  EXPECT_EQ(fixed.back().particles, 20000u) << "disabled, the count stays fixed";
}

// Gaussian clouds the test places itself: one at `pose`, and a second `twin_shift_m` east of it
// when that is not 0 (particles alternate between the two). Asks for KLD sizing after `wait`
// concentrated resamplings.
class CloudsInitializer : public ParticleInitializer {
 public:
  CloudsInitializer(mrpt::math::TPose2D pose, double twin_shift_m, double std_xy_m, double std_phi_rad, int wait = 1)
      : pose_(pose), twin_shift_m_(twin_shift_m), std_xy_m_(std_xy_m), std_phi_rad_(std_phi_rad), wait_(wait) {}
  std::string name() const override { return "clouds"; }
  void initialize(mrpt::slam::CMonteCarloLocalization2D& pf, mrpt::bayes::CParticleFilter::TParticleFilterOptions&,
                  const mrpt::maps::COccupancyGridMap2D&, const mrpt::obs::CSensoryFrame&) override {
    Rng rng(7);
    pf.m_particles.resize(kParticles);
    for (size_t i = 0; i < kParticles; ++i) {
      const double dx = i % 2 ? twin_shift_m_ : 0.0;
      pf.m_particles[i].d = {rng.normal(pose_.x + dx, std_xy_m_), rng.normal(pose_.y, std_xy_m_),
                             rng.normal(pose_.phi, std_phi_rad_)};
      pf.m_particles[i].log_w = 0.0;
    }
  }
  std::optional<KldResampling> kldResampling() const override {
    KldResampling k{{}, SeededInitParams{}.min_particles};
    k.params.concentrated_resamplings = wait_;
    return k;
  }
  static constexpr size_t kParticles = 20000;

 private:
  mrpt::math::TPose2D pose_;
  double twin_shift_m_, std_xy_m_, std_phi_rad_;
  int wait_;
};

// A set gathered in one place shrinks only after it has stayed there for the resamplings asked:
// one scan can gather a uniform start on a wrong place that later scans would spread again.
TEST(SystemSeededMcl, AConcentratedSetWaitsTheResamplingsAskedBeforeShrinking) {
  const RoomTrial rt;
  // The first update that weighs fewer than the start's particles (-1: none did).
  const auto first_shrunk = [&](int wait) {
    MclLocalizer loc(rt.room, std::make_shared<CloudsInitializer>(rt.trial.truth[0], 0.0, 0.1, 0.05, wait), MclParams{});
    for (size_t i = 0; i < rt.steps.size(); ++i)
      if (loc.update(rt.steps[i]).particles < CloudsInitializer::kParticles) return static_cast<int>(i);
    return -1;
  };
  const int at_once = first_shrunk(1), after_three = first_shrunk(3);
  ASSERT_GE(at_once, 1) << "a concentrated cloud should shrink";
  ASSERT_GE(after_three, 0) << "it should shrink once it has waited";
  EXPECT_GE(after_three, at_once + 2) << "shrank before its three resamplings in a row";
}

// A set split between twin rooms, which no scan tells apart, stays split: however peaked each
// half is, it must keep its start's count, since the half that KLD sizing would starve may be
// the right one.
TEST(SystemSeededMcl, ASetSplitBetweenLookAlikePlacesKeepsItsCount) {
  const auto rooms = std::make_shared<const mrpt::maps::COccupancyGridMap2D>(test::twinRooms());
  TrialParams tp;
  tp.steps = 4;
  // The first trial that starts in the west room, so that its twin lies east.
  Trial t;
  for (uint64_t seed = 1; seed < 50 && (t.truth.empty() || t.truth[0].x > test::twinRoomsShiftM()); ++seed)
    t = generateTrial(*rooms, lidarProfileByName("omni_12m"), tp, seed);
  ASSERT_LT(t.truth[0].x, test::twinRoomsShiftM());
  MclLocalizer loc(rooms, std::make_shared<CloudsInitializer>(t.truth[0], test::twinRoomsShiftM(), 0.3, 0.1), MclParams{});
  const auto steps = trialToSteps(t);
  for (size_t i = 0; i < steps.size(); ++i) {
    const auto e = loc.update(steps[i]);
    ASSERT_FALSE(isConcentrated(filterSpread(e.cov), KldResamplingParams{}.only_once_concentrated))
        << "update " << i << ": the twin rooms should keep the set split";
    EXPECT_EQ(e.particles, CloudsInitializer::kParticles) << "update " << i;
  }
}

}  // namespace
}  // namespace krp
