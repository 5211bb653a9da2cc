// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>

namespace krp {

/// The "seismic" diverging colormap (dark blue - blue - white - red - dark red, evenly
/// spaced anchors, linear in between, as matplotlib defines it), as a 256-entry BGR table
/// for cv::LUT: index 0 is the most negative value, 255 the most positive.
const cv::Mat& seismicLutBgr();

}  // namespace krp
