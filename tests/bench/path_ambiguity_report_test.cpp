// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/path_ambiguity_report.h"

#include <gtest/gtest.h>

namespace krp {
namespace {

TrialRecord record(const std::string& method, PathVerdict verdict, bool converged, bool confident_wrong, bool confident_right) {
  TrialRecord r;
  r.world = "warehouse";
  r.lidar = "omni_12m";
  r.method = method;
  r.path.verdict = verdict;
  r.outcome.converged = converged;
  r.outcome.confident_but_wrong = confident_wrong;
  r.outcome.confident_and_right = confident_right;
  return r;
}

TEST(PathAmbiguityReport, SplitsEachMethodsOutcomesByTheTrialsVerdict) {
  const std::vector<TrialRecord> records = {
      record("seeded", PathVerdict::told_apart, true, false, true),
      record("seeded", PathVerdict::told_apart, false, true, false),
      record("seeded", PathVerdict::ambiguous, false, false, false),
      record("seeded", PathVerdict::misleading, false, true, false),
      record("amcl-kld", PathVerdict::told_apart, false, true, false),
      record("amcl-kld", PathVerdict::not_checked, true, false, true),
  };
  const auto splits = splitByPathAmbiguity(records);
  ASSERT_EQ(splits.size(), 2u);
  const auto& seeded = splits[0];
  EXPECT_EQ(seeded.method, "seeded");
  EXPECT_EQ(seeded.told_apart.trials, 2);
  EXPECT_EQ(seeded.told_apart.success, 1);
  EXPECT_EQ(seeded.told_apart.confident_wrong, 1);
  EXPECT_EQ(seeded.told_apart.confident_right, 1);
  EXPECT_EQ(seeded.ambiguous.trials, 1);
  EXPECT_EQ(seeded.ambiguous.success, 0);
  EXPECT_EQ(seeded.misleading.trials, 1);
  EXPECT_EQ(seeded.misleading.confident_wrong, 1);
  EXPECT_EQ(splits[1].told_apart.trials, 1) << "a trial not checked is in no verdict";
  EXPECT_EQ(splits[1].ambiguous.trials + splits[1].misleading.trials, 0);

  const auto md = pathAmbiguitySection(splits, PathAmbiguityParams{});
  EXPECT_NE(md.find("| warehouse | omni_12m | 4 | 2/4 (50 %) | 1/4 (25 %) | 1/4 (25 %) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| warehouse | omni_12m | seeded | 1/2 (50 %) | 1/2 (50 %) | 1/2 (50 %) | 0/1 (0 %)"), std::string::npos) << md;
}

TEST(PathAmbiguityReport, TheSectionSaysHowTheTruthAndThePlacesWereWeighed) {
  const std::vector<TrialRecord> records = {record("seeded", PathVerdict::ambiguous, false, false, false)};
  PathAmbiguityParams params;
  params.truth_offset_steps = 0.5;
  params.tracking.refine_step_m = 0.1;
  params.tracking.refine_step_deg = 2.0;
  params.tracking.finer_refinements = 2;
  params.tracking.first_scan_search_m = 0.4;
  params.tracking.first_scan_search_deg = 5.0;
  const auto md = pathAmbiguitySection(splitByPathAmbiguity(records), params);
  EXPECT_NE(md.find("The truth is weighed as the places are"), std::string::npos) << md;
  EXPECT_NE(md.find("it starts 0.5 of a step off its exact pose"), std::string::npos) << md;
  EXPECT_NE(md.find("on the first scan every side is first moved to its best pose within 0.4 m / 5 deg"), std::string::npos) << md;
  EXPECT_NE(md.find("re-fitted on a 10 cm / 2 deg grid and then on 2 grids of half"), std::string::npos) << md;
  EXPECT_NE(md.find("each place where a method ended away from the truth"), std::string::npos) << md;
}

TEST(PathAmbiguityReport, NoSectionWhenNoTrialWasChecked) {
  const std::vector<TrialRecord> records = {record("seeded", PathVerdict::not_checked, true, false, true)};
  EXPECT_TRUE(splitByPathAmbiguity(records).empty());
  EXPECT_EQ(pathAmbiguitySection(splitByPathAmbiguity(records), PathAmbiguityParams{}), "");
}

}  // namespace
}  // namespace krp
