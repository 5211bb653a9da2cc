// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "mrpt_krp_plugin/bench/reliability.h"
#include "mrpt_krp_plugin/relocalize/confidence_calibration.h"

namespace krp {

struct CalibrationFitParams {
  /// Fewer answers than this are refused: a fit on a handful of trials is noise.
  int min_answers = 20;
  /// Ridge pull of (slope - 1, offset) towards the identity, in units of answers: with every
  /// answer right (nothing to separate) maximum likelihood alone would run off to infinity.
  double prior_weight = 1.0;
  int max_iterations = 100;
};

/// The penalized negative log-likelihood that the fit minimizes: the answers' log loss under
/// sigmoid(slope * logit(confidence) + offset), plus prior_weight / 2 * ((slope - 1)^2 + offset^2).
double calibrationLoss(const std::vector<ConfidenceOutcome>& answers, double slope, double offset,
                       double prior_weight);

/// Fits Platt scaling (ConfidenceCalibration) to raw first-scan confidences and whether each was
/// right, by damped Newton steps on calibrationLoss. std::invalid_argument for too few
/// answers or for confidences that fall as rightness rises (a negative slope).
ConfidenceCalibration fitConfidenceCalibration(const std::vector<ConfidenceOutcome>& answers,
                                               const CalibrationFitParams& params = {});

}  // namespace krp
