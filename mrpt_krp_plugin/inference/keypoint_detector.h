// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "mrpt_krp_plugin/inference/model_manifest.h"
#include "mrpt_krp_plugin/inference/onnx_model.h"
#include "mrpt_krp_plugin/inference/yolo_pose_decode.h"

namespace krp {

/// The keypoint model: seismic SDT image of a submap -> zone detections with their landmarks'
/// image positions.
class KeypointDetector {
 public:
  KeypointDetector(const ModelManifest& manifest, const OnnxRuntimeParams& params = {});

  /// `sdt_bgr` is renderSdtImage()'s output at the manifest's submap size.
  std::vector<PoseDetection> detect(const cv::Mat& sdt_bgr, const PoseDecodeParams& decode = {}) const;

  /// The model's raw `output0`, before decoding.
  Tensor raw(const cv::Mat& sdt_bgr) const;

  /// Decodes a raw `output0` of this model (detect() is decode(raw(image))).
  std::vector<PoseDetection> decode(const Tensor& output0, const PoseDecodeParams& decode = {}) const;

 private:
  ModelManifest manifest_;
  OnnxModel model_;
};

}  // namespace krp
