// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "mrpt_krp_plugin/inference/model_manifest.h"
#include "mrpt_krp_plugin/inference/onnx_model.h"

namespace krp {

/// `path` (one of the manifest's models) read whole, after checking that its bytes are those the
/// manifest describes (ManifestModel::sha256); loading from the returned bytes runs what was
/// checked. A model replaced after krp-train-map wrote the manifest
/// (another training run's file copied over it, a truncated copy) would be fed with the
/// manifest's zones, landmarks and normalization, and answer confidently for the wrong map:
/// InputError naming the file and both hashes instead.
OnnxModelFile requireManifestModelFile(const ManifestModel& model, const std::string& path);

}  // namespace krp
