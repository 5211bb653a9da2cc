// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>

#include "mrpt_krp_plugin/submap/local_grid.h"

namespace krp {

struct SdtImageParams {
  /// Signed distances are divided by this and clipped to [-1, 1] before colouring: walls and
  /// the first `clip_m` of space around them carry the colour gradient [m].
  double clip_m = 2.0;
};

/// Signed distance transform [m], CV_32F: in known-free cells the distance to the nearest
/// obstacle (positive); in obstacle and unknown cells minus the distance to the nearest free
/// cell. With no obstacle (or no free cell) at all, the distances are the image diagonal.
cv::Mat signedDistanceM(const LocalGrid& grid);

/// The keypoint model's input: the SDT normalized by `clip_m` through the seismic colormap
/// (blue = inside obstacles or unseen, white = at a wall, red = open space), 3 channels BGR.
cv::Mat renderSdtImage(const LocalGrid& grid, const SdtImageParams& params = {});

}  // namespace krp
