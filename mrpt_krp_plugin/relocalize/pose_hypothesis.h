// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPose2D.h>

namespace krp {

/// What proposed a hypothesis: the keypoint alignment or a correlative search of the map.
enum class PoseOrigin { kKeypoints, kMatcher };

/// One candidate robot pose from the relocalizer, with the evidence behind it.
struct PoseHypothesis {
  mrpt::math::TPose2D pose;         ///< robot pose in the map (grid) frame
  mrpt::math::CMatrixDouble33 cov;  ///< of (x, y, yaw): the keypoint alignment's, from its residuals
  int zone = -1;                    ///< zone index (manifest order) whose keypoints gave it
  double zone_probability = 0.0;    ///< the classifier's probability of that zone
  int keypoint_inliers = 0;         ///< keypoints that agreed with the alignment
  double alignment_rms_m = 0.0;     ///< RMS keypoint residual of the alignment [m]
  double fit_fraction = 0.0;        ///< scan returns explained by the map at `pose` (ScanFit) [0..1]
  double confidence = 0.0;          ///< probability that this is the robot's pose (HypothesisRanking) [0..1]
  /// Origin kMatcher: the correlative search's score at the grid pose it proposed, before ICP
  /// moved it (MatchSolution::score) [0..1]. Two places of one scan with the same score tie exactly:
  /// which of them a search returns depends on its visiting order.
  double matcher_score = 0.0;
  PoseOrigin origin = PoseOrigin::kKeypoints;
};

}  // namespace krp
