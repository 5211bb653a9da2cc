// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace krp::ros1 {

/// Checks that every string and array length inside a serialized message fits in its bytes.
/// roscpp's deserializers size a vector from the length the message states before reading it, so
/// one corrupt length in a bag makes them allocate up to 16 GB (found by bag_fuzzer: 4 GB for a
/// LaserScan's ranges, 16 s under AddressSanitizer). Empty when the message fits; otherwise what
/// is wrong, naming the field.
std::string laserScanBoundsProblem(const uint8_t* data, size_t size);
std::string tfMessageBoundsProblem(const uint8_t* data, size_t size);

}  // namespace krp::ros1
