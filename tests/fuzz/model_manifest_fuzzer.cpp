// SPDX-License-Identifier: BSD-3-Clause
// manifest.json beside the models. Every bad input must end in an InputError.
#include "fuzz_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/inference/model_manifest.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto& folder = krp::fuzz::scratch();
  folder.write("manifest.json", krp::fuzz::asText(data, size));
  try {
    krp::readModelManifest(folder.path());
  } catch (const krp::InputError&) {
  }
  return 0;
}
