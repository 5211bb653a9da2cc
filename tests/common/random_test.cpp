// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <vector>

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

TEST(Random, ShufflingKeepsTheElementsAndFollowsTheSeed) {
  std::vector<int> v(50);
  for (int i = 0; i < 50; ++i) v[i] = i;
  auto a = v, b = v, c = v;
  Rng(3).shuffle(a);
  Rng(3).shuffle(b);
  Rng(4).shuffle(c);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_NE(a, v) << "50 elements left in order";
  std::sort(a.begin(), a.end());
  EXPECT_EQ(a, v);
}

// Each element should reach the front as often as any other: over 20,000 draws of 3 from 10,
// each lands in the front three about 6,000 times (binomial sd ~65).
TEST(Random, SampleToFrontDrawsEveryElementAlike) {
  std::vector<int> hits(10, 0);
  Rng rng(11);
  for (int trial = 0; trial < 20000; ++trial) {
    std::vector<int> v{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    rng.sampleToFront(v, 3);
    for (int k = 0; k < 3; ++k) ++hits[v[k]];
    std::vector<int> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  }
  for (int h : hits) EXPECT_NEAR(h, 6000, 400);
  std::vector<int> two{1, 2};
  rng.sampleToFront(two, 5);  // asks for more than there are
  EXPECT_EQ(two.size(), 2u);
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
