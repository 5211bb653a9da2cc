// SPDX-License-Identifier: BSD-3-Clause
// The binary map formats: MRPT .gridmap (plain and gzip) and OctoMap .bt / .ot. The first byte
// picks the format, the rest is the file. Every bad input must end in an InputError.
#include <array>
#include <string>

#include "fuzz_file.h"
#include "fuzz_map_limits.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/map_loader.h"

namespace {
const std::array<std::string, 4> kNames = {"map.gridmap", "map.gridmap.gz", "map.bt", "map.ot"};
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const auto& name = kNames[data[0] % kNames.size()];
  try {
    const auto file = krp::fuzz::scratch().write(name, krp::fuzz::asText(data + 1, size - 1));
    krp::loadOccupancyMap(file, krp::fuzz::fuzzMapLimits());
  } catch (const krp::InputError&) {
  }
  return 0;
}
