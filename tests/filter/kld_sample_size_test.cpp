// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "mrpt_krp_plugin/filter/kld_sample_size.h"

namespace krp {
namespace {

TEST(KldSampleSize, BoundMatchesFoxsFormulaWithAmclsSettings) {
  // (k-1)/(2 eps) (1 - 2/(9(k-1)) + sqrt(2/(9(k-1))) z)^3 with eps 0.01, z 0.99, worked by hand.
  EXPECT_EQ(kldBound(0, 0.01, 0.99), 0u);
  EXPECT_EQ(kldBound(1, 0.01, 0.99), 0u);
  EXPECT_EQ(kldBound(2, 0.01, 0.99), 97u);     // 50 * 1.24447^3 = 96.37
  EXPECT_EQ(kldBound(101, 0.01, 0.99), 5697u);  // 5000 * 1.04445^3 = 5696.9
  // Many bins: close to (k-1) / (2 eps), a little above it.
  const auto many = kldBound(10001, 0.01, 0.99);
  EXPECT_GT(many, 500000u);
  EXPECT_LT(many, 510000u);
  EXPECT_LT(kldBound(2, 0.05, 0.99), kldBound(2, 0.01, 0.99)) << "a looser epsilon needs fewer";
}

TEST(KldSampleSize, AConvergedSetKeepsTheFloorAndASpreadOneKeepsMore) {
  KldSampleSizeParams p;
  // 5,000 draws inside one 0.5 m, 10 deg bin: the floor is enough.
  std::vector<mrpt::math::TPose2D> converged(5000, mrpt::math::TPose2D(2.1, 3.2, 0.05));
  EXPECT_EQ(kldSampleCount(converged, p, 300), 300u);
  // Draws over a 40 x 40 m floor with any heading: each new draw tends to open a new bin, so
  // the bound runs ahead of the count and every draw is kept.
  std::vector<mrpt::math::TPose2D> spread;
  for (int i = 0; i < 5000; ++i)
    spread.emplace_back(std::fmod(i * 7.31, 40.0), std::fmod(i * 3.17, 40.0), std::fmod(i * 0.7, 2 * M_PI) - M_PI);
  EXPECT_EQ(kldSampleCount(spread, p, 300), 5000u);
  // Two places in alternation, with a low floor: the bound for two bins decides.
  std::vector<mrpt::math::TPose2D> two;
  for (int i = 0; i < 5000; ++i) two.emplace_back(i % 2 ? 1.2 : 8.7, 1.2, 0.3);
  EXPECT_EQ(kldSampleCount(two, p, 10), kldBound(2, p.epsilon, p.z));
}

TEST(KldSampleSize, FewerDrawsThanTheFloorAreAllKept) {
  KldSampleSizeParams p;
  std::vector<mrpt::math::TPose2D> draws(100, mrpt::math::TPose2D(0, 0, 0));
  EXPECT_EQ(kldSampleCount(draws, p, 500), 100u);
  EXPECT_EQ(kldSampleCount({}, p, 500), 0u);
}

}  // namespace
}  // namespace krp
