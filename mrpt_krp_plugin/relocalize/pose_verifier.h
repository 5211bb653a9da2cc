// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

#include "mrpt_krp_plugin/relocalize/hypothesis_ranking.h"
#include "mrpt_krp_plugin/relocalize/icp_refiner.h"
#include "mrpt_krp_plugin/relocalize/scan_fit.h"

namespace krp {

struct PoseVerifierParams {
  bool icp_refine = true;  ///< refine each hypothesis by ICP before scoring it
  IcpRefineParams icp;
  ScanFitParams fit;
  HypothesisRankingParams ranking;
};

/// Checks hypotheses against the global map: refines each by ICP, scores it by how much of
/// the scan the map explains there, and ranks them ("not localized" when none is credible).
/// Knows nothing of where the hypotheses came from.
class PoseVerifier {
 public:
  PoseVerifier(const mrpt::maps::COccupancyGridMap2D& map, PoseVerifierParams params = {});

  Ranking verify(const mrpt::obs::CObservation2DRangeScan& scan, std::vector<PoseHypothesis> candidates) const;

  /// verify() in two halves, for callers that add candidates after a first ranking: refine and
  /// score each candidate once (the costly half), then rank any set of scored ones.
  std::vector<PoseHypothesis> refineAndScore(const mrpt::obs::CObservation2DRangeScan& scan,
                                             std::vector<PoseHypothesis> candidates) const;
  Ranking rank(std::vector<PoseHypothesis> scored) const;

  const ScanFitScorer& scorer() const { return scorer_; }

 private:
  PoseVerifierParams params_;
  ScanFitScorer scorer_;
  IcpRefiner icp_;
};

}  // namespace krp
