// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/matcher_relocalizer.h"

#include <cmath>

namespace krp {

MatcherRelocalizer::MatcherRelocalizer(const mrpt::maps::COccupancyGridMap2D& map, MatcherRelocalizerParams params)
    : params_(params), matcher_(map, params.matcher), verifier_(map, params.verifier) {}

Ranking MatcherRelocalizer::relocalize(const mrpt::obs::CObservation2DRangeScan& scan) const {
  std::vector<PoseHypothesis> candidates;
  for (const auto& s : matcher_.match(scan)) {
    PoseHypothesis h;
    h.pose = s.pose;
    // The search grid's quantization: half a cell and half a heading step, as standard deviations.
    h.cov.setZero();
    h.cov(0, 0) = h.cov(1, 1) = std::pow(0.5 * params_.matcher.resolution_m, 2);
    h.cov(2, 2) = std::pow(0.5 * params_.matcher.angular_step_deg * M_PI / 180.0, 2);
    candidates.push_back(h);
  }
  return verifier_.verify(scan, std::move(candidates));
}

}  // namespace krp
