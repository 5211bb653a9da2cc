// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/filter/later_scan_seeding.h"

namespace krp {
namespace {

mrpt::slam::CMonteCarloLocalization2D particlesAt(const mrpt::math::TPose2D& place, std::size_t count) {
  mrpt::slam::CMonteCarloLocalization2D pf;
  pf.m_particles.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    pf.m_particles[i].d = place;
    pf.m_particles[i].log_w = -static_cast<double>(i % 7);  // uneven, as between resamplings
  }
  return pf;
}

PoseHypothesis hypothesisAt(double x, double y, double phi) {
  PoseHypothesis h;
  h.pose = {x, y, phi};
  return h;
}

std::size_t near(const mrpt::slam::CMonteCarloLocalization2D& pf, double x, double y, double phi) {
  std::size_t n = 0;
  for (const auto& p : pf.m_particles)
    n += std::hypot(p.d.x - x, p.d.y - y) < 0.6 && std::abs(mrpt::math::wrapToPi(p.d.phi - phi)) < 0.2;
  return n;
}

TEST(LaterScanSeeding, GivesEachHypothesisWithoutParticlesItsShare) {
  auto pf = particlesAt({1.0, 1.0, 0.0}, 1000);
  Ranking ranking;
  // The filter's own place is among them: it keeps its particles, the two others get 100 each.
  ranking.hypotheses = {hypothesisAt(5.0, 2.0, 0.5), hypothesisAt(1.0, 1.0, 0.0), hypothesisAt(3.0, 4.0, -1.0)};
  Rng rng(1);
  EXPECT_EQ(seedFromLaterScan(pf, ranking, {}, LaterScanSeedingParams{}, rng), 2);
  EXPECT_EQ(pf.size(), 1000u);
  EXPECT_EQ(near(pf, 5.0, 2.0, 0.5), 100u);
  EXPECT_EQ(near(pf, 3.0, 4.0, -1.0), 100u);
  EXPECT_EQ(near(pf, 1.0, 1.0, 0.0), 800u);
  for (const auto& p : pf.m_particles) EXPECT_EQ(p.log_w, 0.0);
}

TEST(LaterScanSeeding, LeavesAFilterThatHoldsEveryHypothesisAsItIs) {
  auto pf = particlesAt({1.0, 1.0, 0.0}, 1000);
  Ranking ranking;
  ranking.hypotheses = {hypothesisAt(1.3, 0.8, 0.1)};
  Rng rng(1);
  EXPECT_EQ(seedFromLaterScan(pf, ranking, {}, LaterScanSeedingParams{}, rng), 0);
  EXPECT_EQ(near(pf, 1.0, 1.0, 0.0), 1000u);
  EXPECT_EQ(pf.m_particles[3].log_w, -3.0) << "weights are reset only when particles move";
}

TEST(LaterScanSeeding, OnlyTheBestHypothesesGetParticles) {
  auto pf = particlesAt({1.0, 1.0, 0.0}, 1000);
  Ranking ranking;
  ranking.hypotheses = {hypothesisAt(5.0, 2.0, 0.5), hypothesisAt(3.0, 4.0, -1.0), hypothesisAt(6.0, 5.0, 2.0)};
  LaterScanSeedingParams p;
  p.max_hypotheses = 2;
  Rng rng(1);
  EXPECT_EQ(seedFromLaterScan(pf, ranking, {}, p, rng), 2);
  EXPECT_EQ(near(pf, 6.0, 5.0, 2.0), 0u);
}

// The hypothesis is where the robot is at the scan; the particles are where it was before this
// update's motion, which the prediction then applies: facing +y and driven 1 m forward to
// (5, 2), it was at (5, 1).
TEST(LaterScanSeeding, MovesTheParticlesBackByTheUpdatesMotion) {
  auto pf = particlesAt({1.0, 1.0, 0.0}, 1000);
  Ranking ranking;
  ranking.hypotheses = {hypothesisAt(5.0, 2.0, M_PI / 2)};
  Rng rng(1);
  ASSERT_EQ(seedFromLaterScan(pf, ranking, mrpt::poses::CPose2D(1.0, 0.0, 0.0), LaterScanSeedingParams{}, rng), 1);
  double x = 0, y = 0, phi = 0;
  std::size_t moved = 0;
  for (const auto& p : pf.m_particles) {
    if (p.d.x < 3.0) continue;  // still at (1, 1)
    x += p.d.x, y += p.d.y, phi += p.d.phi, ++moved;
  }
  ASSERT_EQ(moved, 100u);
  EXPECT_NEAR(x / moved, 5.0, 0.05);
  EXPECT_NEAR(y / moved, 1.0, 0.05);
  EXPECT_NEAR(phi / moved, M_PI / 2, 0.02);
}

TEST(LaterScanSeeding, RefusesParametersOutOfRange) {
  EXPECT_NO_THROW(validate(LaterScanSeedingParams{}));
  // True when the defaults with `change` applied are refused with an InputError.
  const auto refused = [](void (*change)(LaterScanSeedingParams&)) {
    LaterScanSeedingParams p;
    change(p);
    try {
      validate(p);
    } catch (const InputError&) {
      return true;
    }
    return false;
  };
  EXPECT_TRUE(refused([](auto& p) { p.share_per_hypothesis = 0.4; })) << "three hypotheses cannot have 0.4 each";
  EXPECT_TRUE(refused([](auto& p) { p.share_per_hypothesis = 0.0; }));
  EXPECT_TRUE(refused([](auto& p) { p.max_scans = -1; }));
  EXPECT_TRUE(refused([](auto& p) { p.max_hypotheses = 0; }));
  EXPECT_TRUE(refused([](auto& p) { p.spread_xy_m = -0.1; }));
}

}  // namespace
}  // namespace krp
