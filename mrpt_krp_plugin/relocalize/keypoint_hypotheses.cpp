// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/keypoint_hypotheses.h"

namespace krp {

std::vector<PoseHypothesis> keypointHypotheses(const std::vector<PoseDetection>& detections, const LocalGrid& grid,
                                               const std::vector<std::vector<mrpt::math::TPoint2D>>& landmarks,
                                               const std::vector<float>& zone_probabilities,
                                               const KeypointHypothesesParams& params) {
  std::vector<PoseHypothesis> out;
  for (const auto& det : detections) {
    if (det.class_id < 0 || det.class_id >= static_cast<int>(landmarks.size())) continue;
    const auto corrs = keypointCorrespondences(det, grid, landmarks[det.class_id], params.correspondences);
    const auto aligned = alignRansac(corrs, params.ransac);
    if (!aligned) continue;
    PoseHypothesis h;
    h.pose = aligned->fit.pose;
    h.cov = aligned->fit.cov;
    h.zone = det.class_id;
    if (det.class_id < static_cast<int>(zone_probabilities.size())) h.zone_probability = zone_probabilities[det.class_id];
    h.keypoint_inliers = static_cast<int>(aligned->inliers.size());
    h.alignment_rms_m = aligned->fit.rms_m;
    out.push_back(h);
  }
  return out;
}

}  // namespace krp
