// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/submap/local_grid.h"
#include "mrpt_krp_plugin/zones/landmarks.h"

namespace krp {

/// YOLO-pose visibility flags (ultralytics' convention).
enum class KeypointVisibility : int { kOutside = 0, kInsideNotObserved = 1, kObserved = 2 };

struct Keypoint {
  cv::Point2d px;  ///< submap image coordinates (column, row) [px]
  KeypointVisibility visibility = KeypointVisibility::kOutside;
};

struct KeypointLabelParams {
  int observed_radius_cells = 2;  ///< a landmark with an obstacle cell this close in the submap was observed [cells]
  double box_margin_px = 4.0;     ///< the object's box surrounds its in-image keypoints by this much [px]
};

/// The zone's landmarks as keypoints of the submap taken at `robot_pose` (map frame).
std::vector<Keypoint> projectLandmarks(const ZoneLandmarks& landmarks, const mrpt::poses::CPose2D& robot_pose,
                                       const LocalGrid& grid, const KeypointLabelParams& params = {});

/// One ultralytics YOLO-pose label line "class cx cy w h x1 y1 v1 ..." (coordinates
/// normalized by the image size; outside keypoints written as 0 0 0), or nothing when no
/// keypoint falls inside the image (the image is then a background sample).
std::optional<std::string> yoloPoseLabel(int class_id, const std::vector<Keypoint>& keypoints, int image_size_px,
                                         const KeypointLabelParams& params = {});

}  // namespace krp
