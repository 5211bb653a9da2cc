// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/filter_spread.h"

#include <gtest/gtest.h>

#include <cmath>

namespace krp {
namespace {

TEST(FilterSpread, ACloudAlongTheDiagonalIsAsSpreadAsOneAlongAnAxis) {
  // Variance 0.36 m^2 along the 45 deg diagonal, 0.01 m^2 across it: each axis alone shows only
  // about 0.43 m std, under the 0.5 m threshold; the worst direction shows 0.6 m.
  const double along = 0.36, across = 0.01;
  mrpt::math::CMatrixDouble33 cov;
  cov.setZero();
  cov(0, 0) = cov(1, 1) = 0.5 * (along + across);
  cov(0, 1) = cov(1, 0) = 0.5 * (along - across);
  cov(2, 2) = std::pow(2.0 * M_PI / 180.0, 2);
  ASSERT_LT(std::sqrt(cov(0, 0)), 0.5);
  const auto s = filterSpread(cov);
  EXPECT_NEAR(s.xy_std_m, 0.6, 1e-9);
  EXPECT_NEAR(s.phi_std_deg, 2.0, 1e-9);
  EXPECT_FALSE(isConcentrated(s, {}));
}

TEST(FilterSpread, ConcentratedNeedsBothPositionAndHeading) {
  EXPECT_TRUE(isConcentrated({0.1, 2.0}, {}));
  EXPECT_FALSE(isConcentrated({0.1, 12.0}, {}));
  EXPECT_FALSE(isConcentrated({0.6, 2.0}, {}));
  EXPECT_TRUE(isConcentrated({0.6, 2.0}, {1.0, 10.0}));
}

TEST(FilterSpread, RaisedSpreadKeepsWhatIsAlreadyWider) {
  mrpt::math::CMatrixDouble33 cov;
  cov.setZero();
  cov(0, 0) = 0.01;
  cov(1, 1) = 4.0;  // 2 m along y: wider than asked
  cov(0, 1) = cov(1, 0) = 0.005;
  cov(2, 2) = std::pow(1.0 * M_PI / 180.0, 2);
  const auto wide = covarianceWithSpreadAtLeast(cov, 1.0, 20.0);
  EXPECT_DOUBLE_EQ(wide(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(wide(1, 1), 4.0);
  EXPECT_DOUBLE_EQ(wide(0, 1), 0.005) << "the correlation is kept";
  const auto s = filterSpread(wide);
  EXPECT_GE(s.xy_std_m, 2.0);
  EXPECT_NEAR(s.phi_std_deg, 20.0, 1e-9);
  EXPECT_FALSE(isConcentrated(s, {}));
}

}  // namespace
}  // namespace krp
