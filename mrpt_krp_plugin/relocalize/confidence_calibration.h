// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace krp {

/// Platt scaling of the ranking's confidence: calibrated = sigmoid(slope * logit(raw) + offset).
/// The identity (slope 1, offset 0) until fitted on held-out trials (krp-bench --fit-calibration),
/// because a confidence fitted on one map says nothing of another.
struct ConfidenceCalibration {
  double slope = 1.0;
  double offset = 0.0;
  int answers = 0;          ///< how many first-scan answers it was fitted on (0 = not fitted)
  std::string fitted_by;    ///< the command that fitted it

  bool isIdentity() const { return slope == 1.0 && offset == 0.0; }
};

/// logit(raw) for a raw confidence in [0, 1], kept a hair inside (0, 1) so that a softmax that
/// saturated still maps to a finite value (about +-21).
double confidenceLogit(double raw);

/// The calibrated confidence of a raw one in [0, 1].
double calibrateConfidence(const ConfidenceCalibration& calibration, double raw);

/// Reads a calibration YAML (keys slope, offset, answers, fitted_by). InputError naming the file for
/// a missing file, an unknown key, a missing or non-finite slope/offset, or a slope <= 0 (which
/// would rank a better fit below a worse one).
ConfidenceCalibration readConfidenceCalibration(const std::string& path);

/// Writes it atomically, in the format readConfidenceCalibration reads.
void writeConfidenceCalibration(const ConfidenceCalibration& calibration, const std::string& path);

}  // namespace krp
