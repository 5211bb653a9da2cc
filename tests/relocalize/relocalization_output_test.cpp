// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include "mrpt_krp_plugin/relocalize/matcher_relocalizer.h"
#include "mrpt_krp_plugin/relocalize/relocalization_output.h"

namespace krp {
namespace {

RelocalizationResult oneOfEach(double matcher_score) {
  RelocalizationResult r;
  PoseHypothesis from_matcher = hypothesisFromMatch(MatchSolution{{4.0, 5.0, 0.5}, matcher_score}, {});
  from_matcher.zone = 1;
  PoseHypothesis from_keypoints;
  from_keypoints.pose = {1.0, 2.0, 0.0};
  from_keypoints.zone = 0;
  r.ranking.hypotheses = {from_matcher, from_keypoints};
  return r;
}

TEST(RelocalizationOutput, JsonCarriesTheMatcherScoreToTheLastBit) {
  // A score no shorter decimal form gives back: the JSON must not round it.
  const double score = 0.1 + 0.2;
  const auto j = relocalizationJson(oneOfEach(score), {"west", "east"});
  ASSERT_EQ(j["hypotheses"].size(), 2u);
  EXPECT_EQ(j["hypotheses"][0]["origin"], "matcher");
  EXPECT_EQ(j["hypotheses"][0]["matcher_score"].get<double>(), score);
  EXPECT_EQ(j["hypotheses"][0]["zone"], "east");
  // The keypoint alignment has no matcher score: null, not a 0 that reads like a bad match.
  EXPECT_EQ(j["hypotheses"][1]["origin"], "keypoints");
  EXPECT_TRUE(j["hypotheses"][1]["matcher_score"].is_null());
}

TEST(RelocalizationOutput, TextNamesTheMatcherScoreOfMatcherHypothesesOnly) {
  const auto text = relocalizationText(oneOfEach(0.8125), {"west", "east"});
  EXPECT_NE(text.find("from matcher (score 0.812500)"), std::string::npos) << text;
  EXPECT_NE(text.find("from keypoints\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace krp
