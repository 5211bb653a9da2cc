// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/relocalize/ransac_alignment.h"

namespace krp {
namespace {

TEST(RansacAlignment, IgnoresOutliersAndRefitsOnInliers) {
  const mrpt::math::TPose2D truth(20.0, 8.0, -1.2);
  Rng rng(7);
  std::vector<Correspondence2D> c;
  for (int i = 0; i < 6; ++i) {  // inliers with 5 cm noise
    const mrpt::math::TPoint2D p(rng.uniform(-8, 8), rng.uniform(-8, 8));
    auto q = truth.composePoint(p);
    c.push_back({p, {q.x + rng.normal(0, 0.05), q.y + rng.normal(0, 0.05)}, 1.0});
  }
  for (int i = 0; i < 5; ++i)  // outliers: keypoints named as the wrong landmark
    c.push_back({{rng.uniform(-8, 8), rng.uniform(-8, 8)}, {rng.uniform(0, 40), rng.uniform(0, 20)}, 1.0});
  const auto r = alignRansac(c);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(r->fit.pose.x, truth.x, 0.1);
  EXPECT_NEAR(r->fit.pose.y, truth.y, 0.1);
  EXPECT_NEAR(r->fit.pose.phi, truth.phi, 0.02);
  EXPECT_EQ(r->inliers.size(), 6u);
  for (int i : r->inliers) EXPECT_LT(i, 6);
}

TEST(RansacAlignment, NoHypothesisWithoutEnoughAgreement) {
  // Three points whose pairwise distances disagree with their map points: no rigid motion fits.
  std::vector<Correspondence2D> c = {{{0, 0}, {0, 0}, 1}, {{1, 0}, {5, 0}, 1}, {{0, 1}, {0, 9}, 1}};
  EXPECT_FALSE(alignRansac(c).has_value());
  EXPECT_FALSE(alignRansac({}).has_value());
}

TEST(RansacAlignment, SameResultWhateverTheSeedWhenAllPairsAreTried) {
  const mrpt::math::TPose2D truth(3.0, 4.0, 0.7);
  std::vector<Correspondence2D> c;
  for (int i = 0; i < 5; ++i) {
    const mrpt::math::TPoint2D p(i * 1.3 - 2, (i % 3) * 1.7 - 1);
    c.push_back({p, truth.composePoint(p), 1.0});
  }
  RansacAlignmentParams a, b;
  b.seed = 99;
  const auto ra = alignRansac(c, a), rb = alignRansac(c, b);
  ASSERT_TRUE(ra && rb);
  EXPECT_DOUBLE_EQ(ra->fit.pose.x, rb->fit.pose.x);
  EXPECT_DOUBLE_EQ(ra->fit.pose.phi, rb->fit.pose.phi);
}

}  // namespace
}  // namespace krp
