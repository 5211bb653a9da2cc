// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/classification_scores.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace krp {
namespace {

TEST(ClassificationScores, PerfectAnswersScoreOne) {
  const auto s = scoreClassification({0, 0, 1, 1}, {0, 0, 1, 1}, 2);
  EXPECT_DOUBLE_EQ(s.precision, 1.0);
  EXPECT_DOUBLE_EQ(s.recall, 1.0);
  EXPECT_DOUBLE_EQ(s.f1, 1.0);
  EXPECT_DOUBLE_EQ(s.accuracy, 1.0);
}

// Always answering zone 0: zone 0 precision 1/2, recall 1; zone 1 never predicted: 0 and 0.
TEST(ClassificationScores, OneZoneAlwaysIsMacroAveraged) {
  const auto s = scoreClassification({0, 0, 1, 1}, {0, 0, 0, 0}, 2);
  EXPECT_DOUBLE_EQ(s.precision, 0.25);
  EXPECT_DOUBLE_EQ(s.recall, 0.5);
  EXPECT_NEAR(s.f1, (2 * 0.5 * 1.0 / 1.5) / 2, 1e-12);
  EXPECT_DOUBLE_EQ(s.accuracy, 0.5);
}

// No answer is wrong for recall and absent from precision.
TEST(ClassificationScores, NoAnswerCountsAgainstRecallOnly) {
  const auto s = scoreClassification({0, 0, 1, 1}, {0, -1, 1, -1}, 2);
  EXPECT_EQ(s.unanswered, 2);
  EXPECT_DOUBLE_EQ(s.precision, 1.0);
  EXPECT_DOUBLE_EQ(s.recall, 0.5);
  EXPECT_DOUBLE_EQ(s.accuracy, 0.5);
}

TEST(ClassificationScores, RefusesMismatchedInput) {
  EXPECT_THROW(scoreClassification({0, 1}, {0}, 2), std::invalid_argument);
  EXPECT_THROW(scoreClassification({0, 2}, {0, 1}, 2), std::invalid_argument);
  EXPECT_THROW(scoreClassification({0}, {0}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace krp
