// SPDX-License-Identifier: BSD-3-Clause
// A bag for krp-localize --bag. Every bad input must end in an InputError.
#include "bag_reader.h"
#include "fuzz_file.h"
#include "mrpt_krp_plugin/common/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    krp::ros1::readBag(krp::fuzz::scratch().write("input.bag", krp::fuzz::asText(data, size)));
  } catch (const krp::InputError&) {
  }
  return 0;
}
