// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/model_file_check.h"

#include "mrpt_krp_plugin/common/sha256.h"
#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

OnnxModelFile requireManifestModelFile(const ManifestModel& model, const std::string& path) {
  auto file = readOnnxModelFile(path);
  const std::string actual = sha256Hex(file.bytes);
  if (actual != model.sha256)
    throw InputError(path, "is not the model manifest.json describes (sha256 " + actual + ", the manifest says " +
                               model.sha256 + "): it was replaced after krp-train-map wrote the manifest; "
                               "restore the folder krp-train-map wrote, or train again");
  return file;
}

}  // namespace krp
