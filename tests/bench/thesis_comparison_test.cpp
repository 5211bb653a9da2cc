// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/thesis_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mrpt_krp_plugin/bench/thesis_comparison_report.h"

namespace krp {
namespace {

TEST(ThesisComparison, AlignmentScoresCountOnlyAnsweredSamples) {
  const std::vector<mrpt::math::TPose2D> truth{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}};
  const std::vector<std::optional<mrpt::math::TPose2D>> estimate{
      mrpt::math::TPose2D{3, 4, 0}, std::nullopt, mrpt::math::TPose2D{2, 2, 0.1}};
  const auto s = scoreAlignment("m", truth, estimate, 0.5, 10.0);
  EXPECT_EQ(s.answered, 2);
  EXPECT_EQ(s.samples, 3);
  EXPECT_NEAR(s.rmse_m, std::sqrt((25.0 + 0.0) / 2), 1e-9);
  EXPECT_NEAR(s.median_m, 2.5, 1e-9);
  EXPECT_NEAR(s.rmse_deg, std::sqrt((0.1 * 180 / M_PI) * (0.1 * 180 / M_PI) / 2), 1e-9);
  EXPECT_NEAR(s.right_share, 1.0 / 3, 1e-12);
}

// A small run on the office with the shipped models: every method answers the same samples and
// the report carries both tables.
TEST(ThesisComparison, SmallOfficeRunAnswersEverySample) {
  const auto world = readWorld(std::string(KRP_SOURCE_DIR) + "/sim_worlds/office_two_zone/office_two_zone.world.yaml");
  ThesisComparisonParams params;
  params.references_per_zone = 2;
  params.tests_per_zone = 2;
  std::ostringstream progress;
  const auto c = runThesisComparison(world, "omni_12m", std::string(KRP_SOURCE_DIR) + "/models/office_two_zone",
                                     params, progress);
  ASSERT_EQ(c.samples.size(), 4u);
  for (const auto& s : c.samples) {
    EXPECT_GE(s.cnn, 0);
    EXPECT_LT(s.cnn, 2);
    EXPECT_GE(s.sift, -1);
    EXPECT_LT(s.sift, 2);
  }
  EXPECT_EQ(c.cnn.samples, 4);
  ASSERT_EQ(c.alignment.size(), 3u);
  EXPECT_EQ(c.alignment[0].answered, 4) << "ICP from the centre always gives a pose";
  const auto report = thesisComparisonMarkdown(c, "krp-thesis-tables --tests 2");
  EXPECT_NE(report.find("Table 4.4"), std::string::npos);
  EXPECT_NE(report.find("Table 4.5"), std::string::npos);
  EXPECT_NE(report.find("krp-thesis-tables --tests 2"), std::string::npos);
  const std::string csv = thesisComparisonCsv(c);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5) << "a header and one row per sample";
}

}  // namespace
}  // namespace krp
