// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "mrpt_krp_plugin/relocalize/se2_fit.h"

namespace krp {

struct RansacAlignmentParams {
  double inlier_threshold_m = 0.6;  ///< a correspondence this close after the fit supports it [m]
  /// A minimal pair is rejected before fitting when its robot and map distances differ by more
  /// than this: a rigid motion keeps distances [m].
  double pair_distance_tolerance_m = 0.6;
  double min_pair_separation_m = 0.5;  ///< closer pairs give an ill-defined heading [m]
  int min_inliers = 3;                 ///< fewer supporting keypoints is no hypothesis
  /// Up to this many minimal pairs are tried; when there are fewer pairs than this, all of them
  /// are, so the result does not depend on the seed.
  int max_pairs = 500;
  uint64_t seed = 1;
  Se2FitParams fit;
};

struct AlignmentResult {
  Se2Fit fit;                  ///< refitted on the inliers by weighted least squares
  std::vector<int> inliers;    ///< indices into the correspondences
  double inlier_weight = 0.0;  ///< sum of the inliers' weights
};

/// Robust SE(2) alignment: every minimal pair (two correspondences) proposes a pose, the pose
/// whose inliers carry the most weight wins, and it is refitted on them by weighted least
/// squares (twice, so that the inlier set follows the refined pose). Nothing when no pose has
/// `min_inliers` inliers.
std::optional<AlignmentResult> alignRansac(const std::vector<Correspondence2D>& corrs,
                                           const RansacAlignmentParams& params = {});

}  // namespace krp
