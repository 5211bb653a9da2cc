// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/relocalize/confidence_calibration.h"
#include "mrpt_krp_plugin/relocalize/pose_hypothesis.h"

namespace krp {

struct HypothesisRankingParams {
  double merge_distance_m = 0.5;   ///< hypotheses closer than this (and merge_angle) are one [m]
  double merge_angle_deg = 10.0;   ///< [deg]
  /// Confidence is a softmax of sharpness * fit_fraction over the hypotheses and one implicit
  /// "somewhere else" alternative with fit `null_fit_fraction`: a lone hypothesis that explains
  /// no more of the scan than that gets at most one half. Defaults chosen by hand; `calibration`
  /// then maps the softmax to a probability fitted on held-out trials of a map.
  double fit_sharpness = 25.0;
  double null_fit_fraction = 0.6;
  ConfidenceCalibration calibration;  ///< the identity unless fitted (krp-bench --fit-calibration)
  double min_fit_fraction = 0.5;  ///< below this a hypothesis is dropped: the map does not explain the scan
  double min_confidence = 0.8;    ///< the best must reach this to be called localized
  /// ...and explain at least this share of the scan's returns (0 = no such floor). A scan that is
  /// largely clutter or unmapped change fits a wrong place nearly as well as the right one: in
  /// the cluttered office the wrong answers called localized explained 67-90 % of their scans
  /// (krp-bench --steps 0, seeds 1 and 2), while in the uncluttered office 97 % of the right ones
  /// explain more than 90 %. Such a scan is left to the filter, which weighs it with the scans
  /// that follow. Checked on another seed in reports/first_scan_verdict.
  double min_localized_fit_fraction = 0.9;
  int max_hypotheses = 10;        ///< kept after ranking
};

struct Ranking {
  std::vector<PoseHypothesis> hypotheses;  ///< best first, confidence set
  bool localized = false;
  std::string reason;  ///< why not localized (empty when localized)
};

/// Within the merge distance and angle: poses the ranking counts as one place.
bool samePlace(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b, const HypothesisRankingParams& params);

/// InputError naming the first parameter out of its range.
void validate(const HypothesisRankingParams& params);

/// Merges near-duplicate hypotheses (keeping the better fit), drops those the map does not
/// explain, assigns confidences and decides whether the best one is credible.
Ranking rankHypotheses(std::vector<PoseHypothesis> candidates, const HypothesisRankingParams& params = {});

}  // namespace krp
