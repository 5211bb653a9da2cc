// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "mrpt_krp_plugin/inference/model_manifest.h"
#include "mrpt_krp_plugin/inference/onnx_model.h"

namespace krp {

/// The zone classifier: occupancy image of a submap -> probability per zone (manifest order).
class ZoneClassifier {
 public:
  ZoneClassifier(const ModelManifest& manifest, const OnnxRuntimeParams& params = {});

  /// `occupancy` is renderOccupancyImage()'s output at the manifest's submap size.
  std::vector<float> probabilities(const cv::Mat& occupancy) const;

 private:
  ModelManifest manifest_;
  OnnxModel model_;
};

}  // namespace krp
