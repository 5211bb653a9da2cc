// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "mrpt_krp_plugin/common/statistics.h"

namespace krp {
namespace {

TEST(Statistics, MedianIsTheMiddleOrTheMeanOfTheTwoMiddles) {
  EXPECT_NEAR(median({3, 1, 2}), 2.0, 1e-12);
  EXPECT_NEAR(median({4, 1, 2, 3}), 2.5, 1e-12);
  EXPECT_NEAR(median({7}), 7.0, 1e-12);
  EXPECT_TRUE(std::isnan(median({})));
}

TEST(Statistics, QuantileInterpolatesBetweenRanksAsNumpyDoes) {
  // numpy.quantile([10, 20, 30, 40, 50], q): 0 -> 10, 0.25 -> 20, 0.9 -> 46, 1 -> 50.
  const std::vector<double> v{50, 10, 40, 20, 30};
  EXPECT_NEAR(quantile(v, 0.0), 10.0, 1e-12);
  EXPECT_NEAR(quantile(v, 0.25), 20.0, 1e-12);
  EXPECT_NEAR(quantile(v, 0.9), 46.0, 1e-12);
  EXPECT_NEAR(quantile(v, 1.0), 50.0, 1e-12);
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
  EXPECT_THROW(quantile(v, 1.5), std::invalid_argument);
  EXPECT_THROW(quantile(v, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace krp
