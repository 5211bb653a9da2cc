// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "mrpt_krp_plugin/inference/yolo_pose_decode.h"
#include "mrpt_krp_plugin/relocalize/keypoint_correspondences.h"
#include "mrpt_krp_plugin/relocalize/pose_hypothesis.h"
#include "mrpt_krp_plugin/relocalize/ransac_alignment.h"
#include "mrpt_krp_plugin/submap/local_grid.h"

namespace krp {

struct KeypointHypothesesParams {
  KeypointCorrespondenceParams correspondences;
  RansacAlignmentParams ransac;
};

/// One pose hypothesis per detection whose keypoints align robustly with its zone's landmarks
/// (`landmarks[zone][k]`); `zone_probabilities` (classifier output, may be empty) is copied
/// into each hypothesis. Detections of unknown zones are skipped.
std::vector<PoseHypothesis> keypointHypotheses(const std::vector<PoseDetection>& detections, const LocalGrid& grid,
                                               const std::vector<std::vector<mrpt::math::TPoint2D>>& landmarks,
                                               const std::vector<float>& zone_probabilities,
                                               const KeypointHypothesesParams& params = {});

}  // namespace krp
