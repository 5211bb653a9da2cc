// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>

#include "mrpt_krp_plugin/inference/model_manifest.h"
#include "mrpt_krp_plugin/inference/onnx_model.h"

namespace krp {

/// An 8-bit image as a 1 x C x H x W float tensor, (value * scale - mean) / std per element.
/// Grey (CV_8UC1) gives one channel; colour (CV_8UC3, OpenCV's BGR) gives three in RGB order,
/// the order ultralytics trains in.
Tensor imageToTensor(const cv::Mat& image, const InputNormalization& normalization);

}  // namespace krp
