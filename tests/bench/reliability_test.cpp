// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/reliability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace krp {
namespace {

TEST(Reliability, BinsAnswersAndMeasuresTheGapBetweenClaimAndOutcome) {
  // Ten answers at 0.9 of which 9 are right: calibrated. Ten at 0.6, all right: under-confident.
  std::vector<ConfidenceOutcome> answers;
  for (int i = 0; i < 10; ++i) answers.push_back({0.9, i < 9});
  for (int i = 0; i < 10; ++i) answers.push_back({0.6, true});
  answers.push_back({1.0, true});  // the last bin holds its upper edge
  const auto bins = reliabilityTable(answers);
  ASSERT_EQ(bins.size(), 6u);
  EXPECT_EQ(bins[1].answers, 10);  // [0.5, 0.8)
  EXPECT_EQ(bins[1].right, 10);
  EXPECT_EQ(bins[3].answers, 10);  // [0.9, 0.95)
  EXPECT_EQ(bins[3].right, 9);
  EXPECT_NEAR(bins[3].mean_confidence, 0.9, 1e-12);
  EXPECT_EQ(bins[5].answers, 1);
  EXPECT_TRUE(std::isnan(bins[0].mean_confidence));
  // Gaps: 0.4 on ten answers, 0 on ten, 0 on one.
  EXPECT_NEAR(expectedCalibrationError(bins), 4.0 / 21.0, 1e-12);
  const auto md = reliabilityMarkdown(bins);
  EXPECT_NE(md.find("| [0.9, 0.95) | 10 | 0.9 | 90 % (9) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| [0.99, 1] | 1 |"), std::string::npos) << md;
}

TEST(Reliability, RefusesEdgesThatDoNotAscendAndHasNoErrorWithoutAnswers) {
  EXPECT_THROW(reliabilityTable({}, {0.5}), std::invalid_argument);
  EXPECT_THROW(reliabilityTable({}, {0.0, 0.5, 0.5}), std::invalid_argument);
  EXPECT_TRUE(std::isnan(expectedCalibrationError(reliabilityTable({}))));
}

}  // namespace
}  // namespace krp
