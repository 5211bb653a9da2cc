// SPDX-License-Identifier: BSD-3-Clause
// Ground-truth files beside rawlogs (`step x y phi distance_m` per line). Every bad input must end
// in an InputError.
#include "fuzz_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    krp::readGroundTruth(krp::fuzz::scratch().write("groundtruth.txt", krp::fuzz::asText(data, size)));
  } catch (const krp::InputError&) {
  }
  return 0;
}
