// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/pose_verifier.h"

namespace krp {

PoseVerifier::PoseVerifier(const mrpt::maps::COccupancyGridMap2D& map, PoseVerifierParams params)
    : params_(params), scorer_(map, params.fit), icp_(map, params.icp) {
  validate(params_.ranking);
}

Ranking PoseVerifier::verify(const mrpt::obs::CObservation2DRangeScan& scan,
                             std::vector<PoseHypothesis> candidates) const {
  return rank(refineAndScore(scan, std::move(candidates)));
}

std::vector<PoseHypothesis> PoseVerifier::refineAndScore(const mrpt::obs::CObservation2DRangeScan& scan,
                                                         std::vector<PoseHypothesis> candidates) const {
  for (auto& h : candidates) {
    if (params_.icp_refine) h.pose = icp_.refine(scan, h.pose);
    h.fit_fraction = scorer_.score(scan, h.pose).fit_fraction;
  }
  return candidates;
}

Ranking PoseVerifier::rank(std::vector<PoseHypothesis> scored) const {
  return rankHypotheses(std::move(scored), params_.ranking);
}

}  // namespace krp
