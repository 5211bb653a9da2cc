// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/keypoint_correspondences.h"

namespace krp {

std::vector<Correspondence2D> keypointCorrespondences(const PoseDetection& detection, const LocalGrid& grid,
                                                      const std::vector<mrpt::math::TPoint2D>& zone_landmarks,
                                                      const KeypointCorrespondenceParams& params) {
  std::vector<Correspondence2D> out;
  const size_t n = std::min(detection.keypoints.size(), zone_landmarks.size());
  for (size_t k = 0; k < n; ++k) {
    const auto& kp = detection.keypoints[k];
    if (kp.visibility < params.min_visibility) continue;
    // Decoded keypoints are continuous image coordinates; the grid speaks pixel centres.
    const cv::Point2d centre(kp.x - kPixelCentreOffset, kp.y - kPixelCentreOffset);
    out.push_back({grid.pixelToRobot(centre), zone_landmarks[k], double(kp.visibility) * double(detection.score)});
  }
  return out;
}

}  // namespace krp
