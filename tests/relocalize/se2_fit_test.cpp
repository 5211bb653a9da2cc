// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "mrpt_krp_plugin/relocalize/se2_fit.h"

namespace krp {
namespace {

TEST(Se2Fit, RecoversAnExactPoseFromTwoPoints) {
  const mrpt::math::TPose2D truth(12.0, -3.0, 2.5);
  const std::vector<mrpt::math::TPoint2D> robot = {{1.0, 2.0}, {-3.0, 0.5}};
  std::vector<Correspondence2D> c;
  for (const auto& p : robot) c.push_back({p, truth.composePoint(p), 1.0});
  const auto fit = fitSe2(c);
  EXPECT_NEAR(fit.pose.x, truth.x, 1e-9);
  EXPECT_NEAR(fit.pose.y, truth.y, 1e-9);
  EXPECT_NEAR(fit.pose.phi, truth.phi, 1e-9);
  EXPECT_NEAR(fit.rms_m, 0.0, 1e-9);
  // An exact two-point fit is not certainty: the floor on the point noise keeps the covariance open.
  EXPECT_GT(fit.cov(0, 0), 1e-4);
  EXPECT_GT(fit.cov(2, 2), 1e-5);
}

TEST(Se2Fit, WeightsPullTowardsTrustedPoints) {
  // Three points agree on the identity pose; the fourth does not.
  std::vector<Correspondence2D> c = {{{1, 0}, {1, 0}, 1.0}, {{0, 1}, {0, 1}, 1.0}, {{-1, 0}, {-1, 0}, 1.0}};
  c.push_back({{0, -1}, {0.6, -1}, 1e-6});  // a wrong point with almost no weight
  EXPECT_NEAR(fitSe2(c).pose.x, 0.0, 1e-5);
  c.back().weight = 1.0;
  EXPECT_GT(fitSe2(c).pose.x, 0.1);
}

TEST(Se2Fit, CovarianceGrowsWithResidualsAndShrinksWithSpread) {
  const mrpt::math::TPose2D truth(5, 5, 0.3);
  std::vector<Correspondence2D> tight, noisy, spread;
  const std::vector<mrpt::math::TPoint2D> pts = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, -1}};
  for (size_t i = 0; i < pts.size(); ++i) {
    const double e = (i % 2 ? 1.0 : -1.0) * 0.5;  // residuals well above the floor
    tight.push_back({pts[i], truth.composePoint(pts[i]), 1.0});
    noisy.push_back({pts[i], {truth.composePoint(pts[i]).x + e, truth.composePoint(pts[i]).y - e}, 1.0});
    const mrpt::math::TPoint2D far = {pts[i].x * 5, pts[i].y * 5};
    spread.push_back({far, {truth.composePoint(far).x + e, truth.composePoint(far).y - e}, 1.0});
  }
  EXPECT_GT(fitSe2(noisy).cov(0, 0), 4.0 * fitSe2(tight).cov(0, 0));
  EXPECT_LT(fitSe2(spread).cov(2, 2), 0.1 * fitSe2(noisy).cov(2, 2));
}

TEST(Se2Fit, RefusesDegenerateInput) {
  EXPECT_THROW(fitSe2({{{1, 1}, {2, 2}, 1.0}}), std::invalid_argument);
  EXPECT_THROW(fitSe2({{{1, 1}, {2, 2}, 1.0}, {{1, 1}, {3, 3}, 1.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace krp
