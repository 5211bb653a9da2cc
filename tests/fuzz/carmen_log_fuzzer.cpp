// SPDX-License-Identifier: BSD-3-Clause
// CARMEN logs (FLASER, ROBOTLASER1, PARAM and anything else, plain or gzip). Every bad input must
// end in an InputError.
#include "fuzz_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/logs/carmen_log.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    krp::readCarmenLog(krp::fuzz::scratch().write("input.log", krp::fuzz::asText(data, size)));
  } catch (const krp::InputError&) {
  }
  return 0;
}
