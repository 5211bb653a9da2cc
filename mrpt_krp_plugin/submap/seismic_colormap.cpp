// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/seismic_colormap.h"

#include <array>
#include <cmath>

namespace krp {

const cv::Mat& seismicLutBgr() {
  static const cv::Mat lut = [] {
    // RGB anchors at 0, 1/4, 1/2, 3/4, 1.
    constexpr std::array<std::array<double, 3>, 5> kAnchorsRgb = {
        {{0.0, 0.0, 0.3}, {0.0, 0.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, 0.0, 0.0}, {0.5, 0.0, 0.0}}};
    cv::Mat t(1, 256, CV_8UC3);
    for (int i = 0; i < 256; ++i) {
      const double u = i / 255.0 * (kAnchorsRgb.size() - 1);
      const int k = std::min(static_cast<int>(u), static_cast<int>(kAnchorsRgb.size()) - 2);
      const double f = u - k;
      cv::Vec3b bgr;
      for (int c = 0; c < 3; ++c) {
        const double v = (1 - f) * kAnchorsRgb[k][c] + f * kAnchorsRgb[k + 1][c];
        bgr[2 - c] = static_cast<uint8_t>(std::lround(255.0 * v));
      }
      t.at<cv::Vec3b>(0, i) = bgr;
    }
    return t;
  }();
  return lut;
}

}  // namespace krp
