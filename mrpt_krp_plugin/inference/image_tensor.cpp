// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/image_tensor.h"

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

Tensor imageToTensor(const cv::Mat& image, const InputNormalization& n) {
  if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3))
    throw InputError("model input image", "must be a non-empty 8-bit grey or BGR image");
  const int c = image.channels(), h = image.rows, w = image.cols;
  Tensor t;
  t.shape = {1, c, h, w};
  t.values.resize(static_cast<size_t>(c) * h * w);
  const float scale = static_cast<float>(n.scale), mean = static_cast<float>(n.mean);
  const float inv_std = static_cast<float>(1.0 / n.std);
  for (int y = 0; y < h; ++y) {
    const uint8_t* row = image.ptr<uint8_t>(y);
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < c; ++ch) {
        // BGR in memory; plane 0 is red for colour images.
        const int src = c == 3 ? 2 - ch : 0;
        t.values[(static_cast<size_t>(ch) * h + y) * w + x] =
            (static_cast<float>(row[x * c + src]) * scale - mean) * inv_std;
      }
  }
  return t;
}

}  // namespace krp
