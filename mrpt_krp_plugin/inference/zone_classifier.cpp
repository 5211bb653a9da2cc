// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/zone_classifier.h"

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/inference/image_tensor.h"
#include "mrpt_krp_plugin/inference/model_file_check.h"

namespace krp {

ZoneClassifier::ZoneClassifier(const ModelManifest& manifest, const OnnxRuntimeParams& params)
    : manifest_(manifest), model_(requireManifestModelFile(manifest.classifier, manifest.classifierPath()), params) {}

std::vector<float> ZoneClassifier::probabilities(const cv::Mat& occupancy) const {
  const int size = manifest_.submap_size_px;
  if (occupancy.rows != size || occupancy.cols != size || occupancy.type() != CV_8UC1)
    throw InputError("zone classifier input", "expected a " + std::to_string(size) + " x " + std::to_string(size) +
                                                  " grey occupancy image (the manifest's submap size)");
  const Tensor out = model_.run(imageToTensor(occupancy, manifest_.classifier.normalization));
  if (out.values.size() != manifest_.zones.size())
    throw InputError(manifest_.classifierPath(), "gives " + std::to_string(out.values.size()) +
                                                     " outputs for the manifest's " +
                                                     std::to_string(manifest_.zones.size()) + " zones");
  return out.values;
}

}  // namespace krp
