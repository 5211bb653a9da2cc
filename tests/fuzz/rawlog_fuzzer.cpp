// SPDX-License-Identifier: BSD-3-Clause
// MRPT rawlogs, through the project's reader and MRPT's deserializer. Every bad input should end
// in an InputError. MRPT's deserializer crashes on some corrupt records (a SEGV in
// CActionRobotMovement2D::serializeFrom, found by this fuzzer); readRawlog contains that in a
// child process, so each input costs a fork and the target is too slow for the CI run:
// `ctest -L fuzz_third_party` in build-sanitize/ runs it.
#include "fuzz_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    krp::readRawlog(krp::fuzz::scratch().write("log.rawlog", krp::fuzz::asText(data, size)));
  } catch (const krp::InputError&) {
  }
  return 0;
}
