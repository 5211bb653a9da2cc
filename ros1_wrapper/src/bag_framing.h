// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>

namespace krp::ros1 {

/// Checks a bag's record framing before rosbag opens it. rosbag (and roscpp's header parser it
/// calls) trusts the lengths and positions a bag stores: a corrupt one makes them read past
/// their buffers (found by bag_fuzzer). Checked here: the format 2.0 magic; every record's header
/// and data lengths and every header field inside the file; connection headers; the index and
/// chunk positions pointing at records of the right kind; in every chunk (bz2 and lz4 ones
/// decompressed first), the inner records and the message offsets of their index records.
/// Throws InputError naming the file and the first problem.
void checkBagFraming(const std::string& path);

}  // namespace krp::ros1
