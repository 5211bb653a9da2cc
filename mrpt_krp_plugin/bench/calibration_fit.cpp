// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/calibration_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace krp {

namespace {
// The same margin as calibrateConfidence keeps: a saturated softmax still has a finite logit.
constexpr double kConfidenceMargin = 1e-9;
constexpr double kConvergedStep = 1e-10;

double logit(double p) {
  const double q = std::clamp(p, kConfidenceMargin, 1.0 - kConfidenceMargin);
  return std::log(q / (1.0 - q));
}
}  // namespace

ConfidenceCalibration fitConfidenceCalibration(const std::vector<ConfidenceOutcome>& answers,
                                               const CalibrationFitParams& params) {
  if (static_cast<int>(answers.size()) < params.min_answers)
    throw std::invalid_argument("calibration fit: " + std::to_string(answers.size()) + " answers, at least " +
                                std::to_string(params.min_answers) + " needed");
  double a = 1.0, b = 0.0;  // start at the identity, where the prior pulls
  const double lambda = params.prior_weight;
  for (int it = 0; it < params.max_iterations; ++it) {
    double ga = lambda * (a - 1.0), gb = lambda * b, haa = lambda, hab = 0.0, hbb = lambda;
    for (const auto& ans : answers) {
      const double x = logit(ans.confidence);
      const double p = 1.0 / (1.0 + std::exp(-(a * x + b)));
      const double residual = p - (ans.right ? 1.0 : 0.0), w = p * (1.0 - p);
      ga += residual * x;
      gb += residual;
      haa += w * x * x;
      hab += w * x;
      hbb += w;
    }
    const double det = haa * hbb - hab * hab;
    const double da = (hbb * ga - hab * gb) / det, db = (haa * gb - hab * ga) / det;
    a -= da;
    b -= db;
    if (std::abs(da) + std::abs(db) < kConvergedStep) break;
  }
  if (!(a > 0.0))
    throw std::invalid_argument("calibration fit: the confidence falls as rightness rises (slope " + std::to_string(a) +
                                "); it cannot be calibrated by scaling");
  ConfidenceCalibration c;
  c.slope = a;
  c.offset = b;
  c.answers = static_cast<int>(answers.size());
  return c;
}

}  // namespace krp
