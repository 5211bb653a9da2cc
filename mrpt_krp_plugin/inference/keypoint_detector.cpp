// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/keypoint_detector.h"

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/inference/image_tensor.h"
#include "mrpt_krp_plugin/inference/model_file_check.h"

namespace krp {

KeypointDetector::KeypointDetector(const ModelManifest& manifest, const OnnxRuntimeParams& params)
    : manifest_(manifest), model_(requireManifestModelFile(manifest.keypoints, manifest.keypointsPath()), params) {}

Tensor KeypointDetector::raw(const cv::Mat& sdt_bgr) const {
  const int size = manifest_.submap_size_px;
  if (sdt_bgr.rows != size || sdt_bgr.cols != size || sdt_bgr.type() != CV_8UC3)
    throw InputError("keypoint model input", "expected a " + std::to_string(size) + " x " + std::to_string(size) +
                                                 " colour SDT image (the manifest's submap size)");
  return model_.run(imageToTensor(sdt_bgr, manifest_.keypoints.normalization));
}

std::vector<PoseDetection> KeypointDetector::decode(const Tensor& output0, const PoseDecodeParams& params) const {
  return decodeYoloPose(output0, static_cast<int>(manifest_.zones.size()), manifest_.keypointsPerZone(),
                        manifest_.submap_size_px, manifest_.submap_size_px, params);
}

std::vector<PoseDetection> KeypointDetector::detect(const cv::Mat& sdt_bgr, const PoseDecodeParams& params) const {
  return decode(raw(sdt_bgr), params);
}

}  // namespace krp
