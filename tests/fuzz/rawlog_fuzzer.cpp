// SPDX-License-Identifier: BSD-3-Clause
// MRPT rawlogs, through the project's reader and MRPT's deserializer. Every bad input should end
// in an InputError. MRPT's deserializer crashes on some corrupt records (a null read in
// CActionRobotMovement2D::serializeFrom, found by this fuzzer; corpus
// mrpt_null_action_segv_crash); readRawlog contains that in a child process, so each input costs a
// fork. The CTest run caps single allocations at 256 MB (tests/fuzz/CMakeLists.txt) so that a
// child asking for the gigabytes a corrupt record announces ends at once.
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
