// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/matcher_relocalizer.h"

#include <cmath>

namespace krp {

PoseHypothesis hypothesisFromMatch(const MatchSolution& solution, const CorrelativeMatcherParams& params) {
  PoseHypothesis h;
  h.pose = solution.pose;
  h.origin = PoseOrigin::kMatcher;
  h.matcher_score = solution.score;
  h.cov.setZero();
  h.cov(0, 0) = h.cov(1, 1) = std::pow(0.5 * params.resolution_m, 2);
  h.cov(2, 2) = std::pow(0.5 * params.angular_step_deg * M_PI / 180.0, 2);
  return h;
}

MatcherRelocalizer::MatcherRelocalizer(const mrpt::maps::COccupancyGridMap2D& map, MatcherRelocalizerParams params)
    : params_(params), matcher_(map, params.matcher), verifier_(map, params.verifier) {}

Ranking MatcherRelocalizer::relocalize(const mrpt::obs::CObservation2DRangeScan& scan) const {
  std::vector<PoseHypothesis> candidates;
  for (const auto& s : matcher_.match(scan)) candidates.push_back(hypothesisFromMatch(s, params_.matcher));
  return verifier_.verify(scan, std::move(candidates));
}

}  // namespace krp
