// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"
#include "mrpt_krp_plugin/relocalize/pose_verifier.h"

namespace krp {

struct MatcherRelocalizerParams {
  CorrelativeMatcherParams matcher;
  PoseVerifierParams verifier;
};

/// A matcher solution as a hypothesis: its covariance is the search grid's quantization, half a
/// cell and half a heading step as standard deviations.
PoseHypothesis hypothesisFromMatch(const MatchSolution& solution, const CorrelativeMatcherParams& params);

/// The `global-matcher` baseline: the correlative matcher's solutions, verified and ranked
/// exactly as the learned relocalizer's hypotheses are, so the two differ only in where the
/// candidates come from.
class MatcherRelocalizer {
 public:
  MatcherRelocalizer(const mrpt::maps::COccupancyGridMap2D& map, MatcherRelocalizerParams params = {});
  Ranking relocalize(const mrpt::obs::CObservation2DRangeScan& scan) const;

 private:
  MatcherRelocalizerParams params_;
  CorrelativeMatcher matcher_;
  PoseVerifier verifier_;
};

}  // namespace krp
