// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>
#include <mrpt/random/RandomGenerators.h>

#include "mrpt_krp_plugin/common/random.h"

namespace krp {
namespace {

TEST(Random, SameSeedSameSequence) {
  Rng a(42), b(42), c(43);
  for (int i = 0; i < 100; ++i) {
    const double x = a.normal(0, 1);
    EXPECT_EQ(x, b.normal(0, 1));
    (void)c;
  }
  EXPECT_NE(Rng(42).uniform(0, 1), Rng(43).uniform(0, 1));
}

TEST(Random, ReseedingMrptIgnoresWhatRanBefore) {
  auto& g = mrpt::random::getRandomGenerator();
  reseedMrptGlobalRandom(7);
  const double first = g.drawGaussian1D_normalized();
  // Leave an odd number of normal draws behind, then reseed: the same value must follow.
  g.drawGaussian1D_normalized();
  g.drawGaussian1D_normalized();
  g.drawGaussian1D_normalized();
  reseedMrptGlobalRandom(7);
  EXPECT_EQ(first, g.drawGaussian1D_normalized());
}

TEST(Random, DerivedSeedsDiffer) {
  EXPECT_NE(deriveSeed(1, 0), deriveSeed(1, 1));
  EXPECT_NE(deriveSeed(1, 0), deriveSeed(2, 0));
  EXPECT_EQ(deriveSeed(5, 9), deriveSeed(5, 9));
}

}  // namespace
}  // namespace krp
