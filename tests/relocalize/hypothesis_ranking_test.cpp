// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_ranking.h"

namespace krp {
namespace {

PoseHypothesis at(double x, double y, double phi, double fit) {
  PoseHypothesis h;
  h.pose = {x, y, phi};
  h.fit_fraction = fit;
  return h;
}

TEST(HypothesisRanking, ALoneGoodFitIsLocalized) {
  const auto r = rankHypotheses({at(1, 2, 0, 0.95)});
  ASSERT_EQ(r.hypotheses.size(), 1u);
  EXPECT_TRUE(r.localized) << r.reason;
  EXPECT_GT(r.hypotheses[0].confidence, 0.99);
}

TEST(HypothesisRanking, TwoEquallyGoodPlacesAreAmbiguous) {
  const auto r = rankHypotheses({at(1, 2, 0, 0.95), at(30, 2, 0, 0.94)});
  ASSERT_EQ(r.hypotheses.size(), 2u);
  EXPECT_FALSE(r.localized);
  EXPECT_NE(r.reason.find("ambiguous"), std::string::npos);
  EXPECT_NEAR(r.hypotheses[0].confidence + r.hypotheses[1].confidence, 1.0, 0.01);
}

TEST(HypothesisRanking, MergesDuplicatesKeepingTheBetterFit) {
  const auto r = rankHypotheses({at(1, 2, 0, 0.8), at(1.1, 2.1, 0.05, 0.9), at(1, 2, 1.0, 0.7)});
  ASSERT_EQ(r.hypotheses.size(), 2u);  // the third is turned by about 55 deg: another hypothesis
  EXPECT_DOUBLE_EQ(r.hypotheses[0].fit_fraction, 0.9);
  EXPECT_DOUBLE_EQ(r.hypotheses[0].pose.x, 1.1);
}

TEST(HypothesisRanking, AScanLargelyUnexplainedIsNotLocalizedEvenByALoneHypothesis) {
  const auto r = rankHypotheses({at(1, 2, 0, 0.85)});
  ASSERT_EQ(r.hypotheses.size(), 1u);
  EXPECT_GT(r.hypotheses[0].confidence, 0.99) << "no rival place: the softmax alone would say localized";
  EXPECT_FALSE(r.localized);
  EXPECT_NE(r.reason.find("unexplained"), std::string::npos) << r.reason;
  HypothesisRankingParams off;
  off.min_localized_fit_fraction = 0.0;
  EXPECT_TRUE(rankHypotheses({at(1, 2, 0, 0.85)}, off).localized);
}

TEST(HypothesisRanking, RefusesParametersOutOfRange) {
  EXPECT_NO_THROW(validate(HypothesisRankingParams{}));
  for (double bad : {-0.1, 1.5, std::nan("")}) {
    HypothesisRankingParams p;
    p.min_localized_fit_fraction = bad;
    EXPECT_THROW(validate(p), InputError) << bad;
  }
  HypothesisRankingParams p;
  p.fit_sharpness = 0.0;
  EXPECT_THROW(validate(p), InputError);
}

TEST(HypothesisRanking, PoorFitsAreNotLocalized) {
  const auto r = rankHypotheses({at(1, 2, 0, 0.3)});
  EXPECT_TRUE(r.hypotheses.empty());
  EXPECT_FALSE(r.localized);
  EXPECT_NE(r.reason.find("explains"), std::string::npos);
  EXPECT_FALSE(rankHypotheses({}).localized);
}

}  // namespace
}  // namespace krp
