// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/hypothesis_ranking.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

bool samePlace(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b, const HypothesisRankingParams& p) {
  return std::hypot(a.x - b.x, a.y - b.y) < p.merge_distance_m &&
         std::abs(mrpt::math::wrapToPi(a.phi - b.phi)) < p.merge_angle_deg * M_PI / 180.0;
}

void validate(const HypothesisRankingParams& p) {
  const auto fraction = [](double v, const char* name) {
    if (!(v >= 0.0 && v <= 1.0))
      throw InputError(std::string("hypothesis ranking: ") + name, "must be in [0, 1], got " + std::to_string(v));
  };
  fraction(p.null_fit_fraction, "null_fit_fraction");
  fraction(p.min_fit_fraction, "min_fit_fraction");
  fraction(p.min_confidence, "min_confidence");
  fraction(p.min_localized_fit_fraction, "min_localized_fit_fraction");
  if (!(p.fit_sharpness > 0.0)) throw InputError("hypothesis ranking: fit_sharpness", "must be > 0");
  if (p.max_hypotheses < 1) throw InputError("hypothesis ranking: max_hypotheses", "must be >= 1");
}

Ranking rankHypotheses(std::vector<PoseHypothesis> candidates, const HypothesisRankingParams& params) {
  Ranking r;
  const size_t proposed = candidates.size();
  double best_rejected_fit = 0.0;
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.fit_fraction > b.fit_fraction; });
  for (auto& c : candidates) {
    if (c.fit_fraction < params.min_fit_fraction) {
      best_rejected_fit = std::max(best_rejected_fit, c.fit_fraction);
      continue;
    }
    const bool duplicate = std::any_of(r.hypotheses.begin(), r.hypotheses.end(),
                                       [&](const auto& kept) { return samePlace(kept.pose, c.pose, params); });
    if (!duplicate) r.hypotheses.push_back(c);
  }
  // Softmax against the implicit "somewhere else": shift by the largest exponent for stability.
  double top = params.fit_sharpness * params.null_fit_fraction;
  for (const auto& h : r.hypotheses) top = std::max(top, params.fit_sharpness * h.fit_fraction);
  double total = std::exp(params.fit_sharpness * params.null_fit_fraction - top);
  for (const auto& h : r.hypotheses) total += std::exp(params.fit_sharpness * h.fit_fraction - top);
  for (auto& h : r.hypotheses)
    h.confidence = calibrateConfidence(params.calibration, std::exp(params.fit_sharpness * h.fit_fraction - top) / total);
  if (static_cast<int>(r.hypotheses.size()) > params.max_hypotheses) r.hypotheses.resize(params.max_hypotheses);

  std::ostringstream why;
  if (r.hypotheses.empty()) {
    if (proposed == 0)
      why << "no hypothesis: no detected keypoints aligned with their landmarks";
    else
      why << "no hypothesis explains the scan: best fit " << best_rejected_fit << " < " << params.min_fit_fraction;
  } else if (r.hypotheses.front().confidence < params.min_confidence) {
    why << "ambiguous: best confidence " << r.hypotheses.front().confidence << " < " << params.min_confidence
        << " (" << r.hypotheses.size() << " distinct hypotheses)";
  } else if (r.hypotheses.front().fit_fraction < params.min_localized_fit_fraction) {
    why << "scan largely unexplained: the best pose explains " << r.hypotheses.front().fit_fraction
        << " of its returns < " << params.min_localized_fit_fraction << " (clutter or a changed map: one scan cannot vouch for it)";
  }
  r.reason = why.str();
  r.localized = r.reason.empty();
  return r;
}

}  // namespace krp
