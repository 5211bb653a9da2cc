// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/zones/landmarks.h"

namespace krp {

/// Landmarks as stored beside a map:
///   method: shi-tomasi-farthest-point
///   keypoints_per_zone: 8
///   zones:
///     - zone: lobby
///       points: [[x0, y0], ...]     # grid-frame metres, keypoint order
/// The method and K are recorded so a model can be matched against the landmarks it learned.
void writeLandmarksYaml(const std::vector<ZoneLandmarks>& landmarks, const LandmarkParams& params,
                        const std::string& path);

/// Reads the file back; every zone must hold exactly K points. Throws InputError naming the
/// file and the problem.
std::vector<ZoneLandmarks> readLandmarksYaml(const std::string& path);

}  // namespace krp
