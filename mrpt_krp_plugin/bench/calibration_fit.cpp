// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/calibration_fit.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace krp {

namespace {
constexpr double kConvergedStep = 1e-10;
constexpr double kConvergedLoss = 1e-12;
constexpr int kMaxHalvings = 60;

/// An answer as the fit sees it: the logit of its raw confidence, computed once.
struct LogitOutcome {
  double x;
  bool right;
};

std::vector<LogitOutcome> logitOutcomes(const std::vector<ConfidenceOutcome>& answers) {
  std::vector<LogitOutcome> out;
  out.reserve(answers.size());
  for (const auto& a : answers) out.push_back({confidenceLogit(a.confidence), a.right});
  return out;
}

double lossOf(const std::vector<LogitOutcome>& points, double slope, double offset, double prior_weight) {
  double loss = 0.5 * prior_weight * ((slope - 1.0) * (slope - 1.0) + offset * offset);
  for (const auto& pt : points) {
    // -log sigmoid(z) for a right answer, -log(1 - sigmoid(z)) for a wrong one, without overflow.
    const double z = slope * pt.x + offset, signed_z = pt.right ? z : -z;
    loss += signed_z > 0 ? std::log1p(std::exp(-signed_z)) : -signed_z + std::log1p(std::exp(signed_z));
  }
  return loss;
}
}  // namespace

double calibrationLoss(const std::vector<ConfidenceOutcome>& answers, double slope, double offset,
                       double prior_weight) {
  return lossOf(logitOutcomes(answers), slope, offset, prior_weight);
}

ConfidenceCalibration fitConfidenceCalibration(const std::vector<ConfidenceOutcome>& answers,
                                               const CalibrationFitParams& params) {
  if (static_cast<int>(answers.size()) < params.min_answers)
    throw std::invalid_argument("calibration fit: " + std::to_string(answers.size()) + " answers, at least " +
                                std::to_string(params.min_answers) + " needed");
  const auto points = logitOutcomes(answers);
  double a = 1.0, b = 0.0;  // start at the identity, where the prior pulls
  const double lambda = params.prior_weight;
  double loss = lossOf(points, a, b, lambda);
  bool converged = false;
  for (int it = 0; it < params.max_iterations && !converged; ++it) {
    double ga = lambda * (a - 1.0), gb = lambda * b, haa = lambda, hab = 0.0, hbb = lambda;
    for (const auto& pt : points) {
      const double p = 1.0 / (1.0 + std::exp(-(a * pt.x + b)));
      const double residual = p - (pt.right ? 1.0 : 0.0), w = p * (1.0 - p);
      ga += residual * pt.x;
      gb += residual;
      haa += w * pt.x * pt.x;
      hab += w * pt.x;
      hbb += w;
    }
    const double det = haa * hbb - hab * hab;
    const double da = (hbb * ga - hab * gb) / det, db = (haa * gb - hab * ga) / det;
    // Newton's full step overshoots where confidences saturate (logits near +-20): halve it
    // until the loss falls, as a damped Newton method must.
    double step = 1.0, next = loss;
    for (int halving = 0; halving < kMaxHalvings; ++halving, step *= 0.5) {
      next = lossOf(points, a - step * da, b - step * db, lambda);
      if (next <= loss) break;
    }
    if (next > loss) break;  // no step lowers the loss: at the minimum to rounding
    a -= step * da;
    b -= step * db;
    converged = step * (std::abs(da) + std::abs(db)) < kConvergedStep || loss - next < kConvergedLoss;
    loss = next;
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
