// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/thread_cpu_time.h"
#include "mrpt_krp_plugin/filter/free_cells.h"
#include "mrpt_krp_plugin/filter/seeded_initializer.h"
#include "support/test_maps.h"

namespace krp {
namespace {

mrpt::obs::CSensoryFrame frameWithScan() {
  mrpt::obs::CSensoryFrame sf;
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->resizeScan(10);
  sf.insert(scan);
  return sf;
}

PoseHypothesis hypothesis(double x, double y, double confidence) {
  PoseHypothesis h;
  h.pose = {x, y, 0.5};
  h.cov.setZero();
  h.cov(0, 0) = h.cov(1, 1) = 0.04;
  h.cov(2, 2) = 0.01;
  h.confidence = confidence;
  return h;
}

size_t near(const mrpt::slam::CMonteCarloLocalization2D& pf, double x, double y, double radius) {
  size_t n = 0;
  for (const auto& p : pf.m_particles) n += std::hypot(p.d.x - x, p.d.y - y) < radius;
  return n;
}

TEST(SeededInitializer, SplitsParticlesByConfidenceAndKeepsAUniformShare) {
  const auto room = test::asymmetricRoom();
  Ranking ranking;
  ranking.hypotheses = {hypothesis(5.5, 2.0, 0.75), hypothesis(1.5, 5.0, 0.25)};
  SeededInitParams p;
  p.particles_per_hypothesis = 1000;
  p.uniform_fraction = 0.1;
  SeededInitializer init([&](const auto&) { return ranking; }, p);
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  init.initialize(pf, o, room, frameWithScan());

  ASSERT_TRUE(init.lastSeeding().has_value());
  EXPECT_FALSE(init.lastSeeding()->fell_back_to_uniform);
  EXPECT_EQ(pf.size(), 2223u);  // ceil(2000 / 0.9)
  EXPECT_EQ(init.lastSeeding()->uniform_particles, 222u);
  // 4 sigma of 0.2 m holds nearly all of a hypothesis's particles; the uniform share adds a few.
  const double seeded = 2223 - 222;
  EXPECT_NEAR(near(pf, 5.5, 2.0, 0.8) / seeded, 0.75, 0.03);
  EXPECT_NEAR(near(pf, 1.5, 5.0, 0.8) / seeded, 0.25, 0.03);
  size_t on_free = 0;
  for (const auto& part : pf.m_particles) on_free += room.getPos(part.d.x, part.d.y) > 0.5;
  EXPECT_GT(on_free, pf.size() * 9 / 10);
}

TEST(SeededInitializer, NoUniformShareWhenAskedAndUniformFallbackWithoutHypotheses) {
  const auto room = test::asymmetricRoom();
  Ranking one, none;
  one.hypotheses = {hypothesis(5.5, 2.0, 1.0)};
  SeededInitParams p;
  p.uniform_fraction = 0.0;
  SeededInitializer seeded([&](const auto&) { return one; }, p);
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  seeded.initialize(pf, o, room, frameWithScan());
  EXPECT_EQ(pf.size(), p.min_particles);
  EXPECT_EQ(near(pf, 5.5, 2.0, 1.0), pf.size());

  p.fallback.particles = 3000;
  SeededInitializer fallback([&](const auto&) { return none; }, p);
  fallback.initialize(pf, o, room, frameWithScan());
  EXPECT_TRUE(fallback.lastSeeding()->fell_back_to_uniform);
  EXPECT_EQ(pf.size(), 3000u);
  EXPECT_LT(near(pf, 5.5, 2.0, 1.0), 300u);
}

PoseHypothesis withStd(PoseHypothesis h, double std_xy_m, double std_yaw_rad) {
  h.cov(0, 0) = h.cov(1, 1) = std_xy_m * std_xy_m;
  h.cov(2, 2) = std_yaw_rad * std_yaw_rad;
  return h;
}

// With count_from_spread the prior's own KLD bound sizes the set: one tight pose needs few
// particles, two tight poses more, a wide one the cap.
TEST(SeededInitializer, CountFromSpreadGrowsWithTheHypothesesSpread) {
  const auto room = test::asymmetricRoom();
  SeededInitParams p;
  p.count_from_spread = KldSampleSizeParams{};
  p.min_particles = 100;
  const auto count = [&](std::vector<PoseHypothesis> hyps) {
    Ranking r;
    r.hypotheses = std::move(hyps);
    SeededInitializer init([&](const auto&) { return r; }, p);
    mrpt::slam::CMonteCarloLocalization2D pf;
    mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
    init.initialize(pf, o, room, frameWithScan());
    EXPECT_EQ(init.lastSeeding()->particles, pf.size());
    EXPECT_NEAR(static_cast<double>(init.lastSeeding()->uniform_particles), p.uniform_fraction * pf.size(), 1.0);
    return pf.size();
  };
  const auto tight = withStd(hypothesis(5.5, 2.0, 1.0), 0.01, 0.001);  // clamped to min_std_*
  const auto one_tight = count({tight});
  const auto two_tight = count({tight, withStd(hypothesis(1.5, 5.0, 1.0), 0.01, 0.001)});
  const auto one_wide = count({withStd(hypothesis(5.5, 2.0, 1.0), 0.8, 0.3)});
  EXPECT_GT(one_tight, p.min_particles) << "a 0.15 m, 3 deg cloud spans a few 0.5 m, 10 deg bins";
  EXPECT_LT(one_tight, 2000u);
  EXPECT_GT(two_tight, one_tight * 3 / 2) << "a second place doubles the occupied bins";
  EXPECT_EQ(one_wide, p.max_particles) << "a 0.8 m, 17 deg cloud needs more than the cap";
  // Unset (the default), the count is the fixed rule's whatever the spread: ceil(250 / 0.95).
  p.count_from_spread.reset();
  EXPECT_EQ(count({withStd(hypothesis(5.5, 2.0, 1.0), 0.8, 0.3)}), 264u);
}

// Only the uniform fallback asks the filter to size its set by KLD sampling: a seeded start is
// concentrated and capped already.
TEST(SeededInitializer, AsksForKldSizingOnlyAfterAUniformFallback) {
  const auto room = test::asymmetricRoom();
  Ranking one, none;
  one.hypotheses = {hypothesis(5.5, 2.0, 1.0)};
  const Ranking* answer = &one;
  SeededInitParams p;
  p.fallback.particles = 3000;
  p.min_particles = 700;
  SeededInitializer init([&](const auto&) { return *answer; }, p);
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  EXPECT_FALSE(init.kldResampling().has_value()) << "nothing seeded yet";
  init.initialize(pf, o, room, frameWithScan());
  EXPECT_FALSE(init.kldResampling().has_value());
  answer = &none;
  init.initialize(pf, o, room, frameWithScan());
  ASSERT_TRUE(init.kldResampling().has_value());
  EXPECT_EQ(init.kldResampling()->min_particles, 700u) << "the seeded floor, whatever the start";
  answer = &one;
  init.initialize(pf, o, room, frameWithScan());
  EXPECT_FALSE(init.kldResampling().has_value()) << "a re-seed after a kidnap is seeded again";

  p.fallback_shrinks.reset();
  SeededInitializer fixed([&](const auto&) { return none; }, p);
  fixed.initialize(pf, o, room, frameWithScan());
  EXPECT_FALSE(fixed.kldResampling().has_value());
}

// The recorded time is "scan to prior" as the bench reports it: it includes the relocalization,
// here a source that spins for a known CPU time, whether it answers or falls back to uniform.
TEST(SeededInitializer, RecordsTheCpuTimeFromScanToPrior) {
  const auto room = test::asymmetricRoom();
  constexpr double kSourceCpuS = 0.03;
  for (const bool answers : {true, false}) {
    SeededInitializer init([&](const auto&) {
      const double start = threadCpuSeconds();
      volatile double sink = 0;
      while (threadCpuSeconds() - start < kSourceCpuS) sink = sink + 1.0;
      Ranking r;
      if (answers) r.hypotheses = {hypothesis(5.5, 2.0, 1.0)};
      return r;
    });
    mrpt::slam::CMonteCarloLocalization2D pf;
    mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
    init.initialize(pf, o, room, frameWithScan());
    EXPECT_EQ(init.lastSeeding()->fell_back_to_uniform, !answers);
    EXPECT_GE(init.lastSeeding()->cpu_s, kSourceCpuS) << "answers: " << answers;
    EXPECT_LT(init.lastSeeding()->cpu_s, 10 * kSourceCpuS) << "a time, not a timestamp";
  }
}

TEST(SeededInitializer, KeepsTheStageTimesATimedSourceGives) {
  const auto room = test::asymmetricRoom();
  Ranking ranking;
  ranking.hypotheses = {hypothesis(5.5, 2.0, 1.0)};
  RelocalizationTimes times;
  times.keypoints_ms = 7.5;
  times.cross_check_ms = 12.0;
  times.total_ms = 21.0;
  const SeededInitializer::TimedHypothesisSource source = [&](const auto&) { return TimedRanking{ranking, times}; };
  SeededInitializer timed(source);
  SeededInitializer untimed([&](const auto&) { return ranking; });
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  timed.initialize(pf, o, room, frameWithScan());
  ASSERT_TRUE(timed.lastSeeding()->stage_times.has_value());
  EXPECT_EQ(timed.lastSeeding()->stage_times->keypoints_ms, 7.5);
  EXPECT_EQ(timed.lastSeeding()->stage_times->cross_check_ms, 12.0);
  EXPECT_EQ(timed.lastSeeding()->stage_times->total_ms, 21.0);
  EXPECT_EQ(timed.lastSeeding()->ranking.hypotheses.size(), 1u);
  untimed.initialize(pf, o, room, frameWithScan());
  EXPECT_FALSE(untimed.lastSeeding()->stage_times.has_value());
  EXPECT_EQ(untimed.lastSeeding()->ranking.hypotheses.size(), 1u);
}

const double kFreeCellMinFreeness = SeededInitParams{}.free_cell_min_freeness;

std::vector<mrpt::math::TPose2D> seededParticles(const mrpt::maps::COccupancyGridMap2D& map,
                                                 std::shared_ptr<const FreeCells> free) {
  Ranking ranking;
  PoseHypothesis h;
  h.pose = {3.0, 2.0, 0.5};
  h.cov.setIdentity();
  h.cov *= 0.01;
  h.confidence = 1.0;
  ranking.hypotheses = {h};
  SeededInitParams p;
  p.uniform_fraction = 0.3;  // enough uniform draws that a wrong cell list would show
  SeededInitializer init([&](const auto&) { return ranking; }, p);
  init.useFreeCells(std::move(free));
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  init.initialize(pf, o, map, frameWithScan());
  std::vector<mrpt::math::TPose2D> out;
  for (const auto& particle : pf.m_particles) out.push_back(particle.d);
  return out;
}

TEST(SeededInitializer, DrawsTheSameParticlesFromGivenFreeCellsAsFromTheMap) {
  const auto room = test::asymmetricRoom();
  const auto afresh = seededParticles(room, nullptr);
  ASSERT_FALSE(afresh.empty());
  EXPECT_EQ(seededParticles(room, std::make_shared<const FreeCells>(room, kFreeCellMinFreeness)), afresh);
  // Cells of another map are not used: the uniform share is drawn from this map's, as without them.
  const auto other = test::twinRooms();
  EXPECT_EQ(seededParticles(room, std::make_shared<const FreeCells>(other, kFreeCellMinFreeness)), afresh);
  // The maps' cells differ enough that drawing from the wrong ones would show.
  EXPECT_NE(freeCellsOf(other, kFreeCellMinFreeness), freeCellsOf(room, kFreeCellMinFreeness));
}

TEST(SeededInitializer, RefusesBadParametersAndFramesWithoutScans) {
  SeededInitParams p;
  p.uniform_fraction = 1.0;
  EXPECT_THROW(SeededInitializer([](const auto&) { return Ranking{}; }, p), InputError);
  SeededInitializer init([](const auto&) { return Ranking{}; });
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  EXPECT_THROW(init.initialize(pf, o, test::asymmetricRoom(), mrpt::obs::CSensoryFrame()), InputError);
}

TEST(SeededInitializer, AnswersForLaterScansWithoutTouchingTheSeedingRecord) {
  int calls = 0;
  SeededInitializer init([&](const auto&) {
    Ranking r;
    r.hypotheses = {hypothesis(1.0 + calls, 2.0, 0.5)};
    ++calls;
    return r;
  });
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  init.initialize(pf, o, test::asymmetricRoom(), frameWithScan());
  const auto later = init.laterHypotheses(frameWithScan());
  ASSERT_TRUE(later.has_value());
  ASSERT_EQ(later->hypotheses.size(), 1u);
  EXPECT_EQ(later->hypotheses[0].pose.x, 2.0) << "the source's answer for this scan";
  EXPECT_EQ(init.lastSeeding()->ranking.hypotheses[0].pose.x, 1.0) << "the record stays the first scan's";
  EXPECT_FALSE(init.laterHypotheses(mrpt::obs::CSensoryFrame()).has_value()) << "no scan, no answer";
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace krp
