// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/relocalize/confidence_calibration.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_ranking.h"
#include "support/test_maps.h"

namespace krp {
namespace {

TEST(ConfidenceCalibration, IdentityUntilFittedThenPlattScaling) {
  const ConfidenceCalibration identity;
  for (double c : {0.0, 0.3, 0.8, 1.0}) EXPECT_DOUBLE_EQ(calibrateConfidence(identity, c), c);
  ConfidenceCalibration sharper;
  sharper.slope = 2.0;
  sharper.offset = -1.0;
  // logit(0.8) = ln 4; 2 ln 4 - 1 = ln 16 - 1; sigmoid of that = 16 / (16 + e).
  EXPECT_NEAR(calibrateConfidence(sharper, 0.8), 16.0 / (16.0 + std::exp(1.0)), 1e-12);
  EXPECT_LT(calibrateConfidence(sharper, 0.5), 0.5);
  // A saturated softmax (raw 0 or 1) still maps through a finite logit.
  EXPECT_GT(calibrateConfidence(sharper, 1.0), 0.999);
  EXPECT_LE(calibrateConfidence(sharper, 1.0), 1.0);
  EXPECT_LT(calibrateConfidence(sharper, 0.0), 1e-9);
  EXPECT_GE(calibrateConfidence(sharper, 0.0), 0.0);
}

TEST(ConfidenceCalibration, RankingAppliesItBeforeTheLocalizedThreshold) {
  PoseHypothesis h;
  h.fit_fraction = 0.7;  // raw confidence sigmoid(25 * 0.1) = 0.92: localized by default
  HypothesisRankingParams params;
  params.min_localized_fit_fraction = 0.0;  // the confidence threshold alone decides here
  const auto raw = rankHypotheses({h}, params);
  ASSERT_TRUE(raw.localized);
  params.calibration.slope = 1.0;
  params.calibration.offset = -2.0;  // an over-confident map: 0.92 means about 0.62
  const auto calibrated = rankHypotheses({h}, params);
  EXPECT_NEAR(calibrated.hypotheses[0].confidence, calibrateConfidence(params.calibration, raw.hypotheses[0].confidence),
              1e-12);
  EXPECT_FALSE(calibrated.localized);
  EXPECT_NE(calibrated.reason.find("ambiguous"), std::string::npos) << calibrated.reason;
}

TEST(ConfidenceCalibration, YamlRoundTripAndBadFilesNamed) {
  const auto dir = test::tempDir("calibration");
  ConfidenceCalibration c;
  c.slope = 1.7;
  c.offset = -0.25;
  c.answers = 100;
  c.fitted_by = "krp-bench --worlds office_two_zone: --seed 11";
  writeConfidenceCalibration(c, dir + "/c.yaml");
  const auto back = readConfidenceCalibration(dir + "/c.yaml");
  EXPECT_DOUBLE_EQ(back.slope, 1.7);
  EXPECT_DOUBLE_EQ(back.offset, -0.25);
  EXPECT_EQ(back.answers, 100);
  EXPECT_EQ(back.fitted_by, c.fitted_by);
  auto messageFor = [&](const std::string& text) {
    std::ofstream(dir + "/bad.yaml") << text;
    try {
      readConfidenceCalibration(dir + "/bad.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(messageFor("slope: 1\noffset: 0\nsharpness: 3\n").find("unknown key 'sharpness'"), std::string::npos);
  EXPECT_NE(messageFor("slope: 1\n").find("missing 'offset'"), std::string::npos);
  EXPECT_NE(messageFor("slope: -1\noffset: 0\n").find("'slope' must be positive"), std::string::npos);
  EXPECT_NE(messageFor("slope: .nan\noffset: 0\n").find("not finite"), std::string::npos);
  EXPECT_NE(messageFor("slope: steep\noffset: 0\n").find("not a number"), std::string::npos);
  EXPECT_THROW(readConfidenceCalibration(dir + "/missing.yaml"), InputError);
}

}  // namespace
}  // namespace krp
