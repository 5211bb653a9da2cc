// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <vector>

#include "mrpt_krp_plugin/inference/yolo_pose_decode.h"
#include "mrpt_krp_plugin/relocalize/se2_fit.h"
#include "mrpt_krp_plugin/submap/local_grid.h"

namespace krp {

struct KeypointCorrespondenceParams {
  /// Keypoints the model gives a lower visibility probability are not used: they are the
  /// landmarks it believes were not observed, whose positions it guesses [0..1].
  float min_visibility = 0.5f;
};

/// The detection's keypoints as robot-frame points paired with their landmarks' map positions
/// (`zone_landmarks[k]` for keypoint k), weighted by visibility times detection score.
/// `grid` gives the submap geometry the image was rendered with.
std::vector<Correspondence2D> keypointCorrespondences(const PoseDetection& detection, const LocalGrid& grid,
                                                      const std::vector<mrpt::math::TPoint2D>& zone_landmarks,
                                                      const KeypointCorrespondenceParams& params = {});

}  // namespace krp
