// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "mrpt_krp_plugin/bench/calibration_fit.h"
#include "mrpt_krp_plugin/common/random.h"

namespace krp {
namespace {

// Answers whose rightness follows a known Platt map of their raw confidence.
std::vector<ConfidenceOutcome> answersFrom(const ConfidenceCalibration& truth, int n, uint64_t seed) {
  Rng rng(seed);
  std::vector<ConfidenceOutcome> out;
  for (int i = 0; i < n; ++i) {
    const double raw = rng.uniform(0.02, 0.98);
    out.push_back({raw, rng.bernoulli(calibrateConfidence(truth, raw))});
  }
  return out;
}

TEST(CalibrationFit, RecoversTheMapTheAnswersFollow) {
  ConfidenceCalibration truth;
  truth.slope = 2.0;
  truth.offset = -1.0;
  const auto fit = fitConfidenceCalibration(answersFrom(truth, 4000, 3));
  EXPECT_NEAR(fit.slope, 2.0, 0.2);
  EXPECT_NEAR(fit.offset, -1.0, 0.2);
  EXPECT_EQ(fit.answers, 4000);
  // Answers that are already calibrated fit (close to) the identity.
  const auto identity = fitConfidenceCalibration(answersFrom(ConfidenceCalibration{}, 4000, 4));
  EXPECT_NEAR(identity.slope, 1.0, 0.15);
  EXPECT_NEAR(identity.offset, 0.0, 0.15);
}

TEST(CalibrationFit, AllRightStaysFiniteAndRaisesTheConfidence) {
  std::vector<ConfidenceOutcome> answers;
  for (int i = 0; i < 50; ++i) answers.push_back({0.5 + 0.009 * i, true});
  const auto fit = fitConfidenceCalibration(answers);
  EXPECT_TRUE(std::isfinite(fit.slope) && std::isfinite(fit.offset));
  EXPECT_GT(calibrateConfidence(fit, 0.6), 0.6) << "every answer was right: the map is under-confident";
}

// Saturated confidences (many at 0.999+, logits near 20) made undamped Newton steps run off to a
// slope of 563; the fit must land on the loss's minimum.
TEST(CalibrationFit, SaturatedConfidencesStillReachTheMinimum) {
  std::vector<ConfidenceOutcome> answers;
  auto add = [&](double confidence, int right, int wrong) {
    for (int i = 0; i < right; ++i) answers.push_back({confidence, true});
    for (int i = 0; i < wrong; ++i) answers.push_back({confidence, false});
  };
  add(0.40, 2, 0), add(0.47, 0, 1), add(0.52, 0, 2), add(0.6, 3, 4), add(0.9, 23, 3), add(0.99999, 57, 5);
  const CalibrationFitParams params;
  const auto fit = fitConfidenceCalibration(answers, params);
  const double at_fit = calibrationLoss(answers, fit.slope, fit.offset, params.prior_weight);
  EXPECT_LT(at_fit, calibrationLoss(answers, 1.0, 0.0, params.prior_weight));
  for (double da : {-1e-3, 0.0, 1e-3})
    for (double db : {-1e-3, 0.0, 1e-3})
      EXPECT_LE(at_fit, calibrationLoss(answers, fit.slope + da, fit.offset + db, params.prior_weight) + 1e-9)
          << "not a minimum: slope " << fit.slope << " offset " << fit.offset;
  EXPECT_LT(fit.slope, 5.0);
}

TEST(CalibrationFit, RefusesTooFewAnswersAndAnInvertedConfidence) {
  EXPECT_THROW(fitConfidenceCalibration(std::vector<ConfidenceOutcome>(5, {0.9, true})), std::invalid_argument);
  std::vector<ConfidenceOutcome> inverted;
  for (int i = 0; i < 100; ++i) inverted.push_back({i < 50 ? 0.1 : 0.9, i < 50});
  EXPECT_THROW(fitConfidenceCalibration(inverted), std::invalid_argument);
}

}  // namespace
}  // namespace krp
