// SPDX-License-Identifier: BSD-3-Clause
// map_server's YAML + PGM/PNG pair. An input is the YAML text, optionally followed by the marker
// line and the image's bytes; without the marker the image is a small valid PGM, so that the
// fuzzer spends its time on the YAML. Every bad input must end in an InputError.
#include <string>

#include "fuzz_file.h"
#include "fuzz_map_limits.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/map_loader.h"

namespace {
constexpr std::string_view kImageMarker = "\n%%IMAGE%%\n";
const std::string kValidPgm = "P5\n4 4\n255\n" + std::string(16, '\xfe');
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto input = krp::fuzz::asText(data, size);
  const auto marker = input.find(kImageMarker);
  const auto yaml = input.substr(0, marker);
  const auto image = marker == std::string_view::npos ? std::string_view(kValidPgm)
                                                      : input.substr(marker + kImageMarker.size());
  auto& folder = krp::fuzz::scratch();
  folder.write("map.pgm", image);
  folder.write("map.png", image);
  try {
    krp::loadOccupancyMap(folder.write("map.yaml", yaml), krp::fuzz::fuzzMapLimits());
  } catch (const krp::InputError&) {
  }
  return 0;
}
