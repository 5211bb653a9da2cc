// SPDX-License-Identifier: BSD-3-Clause
// The YAML files a user writes by hand: zones, landmarks and sim worlds. The first byte picks
// the reader, the rest is the file. Every bad input must end in an InputError.
#include "fuzz_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "mrpt_krp_plugin/zones/landmarks_yaml.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const auto text = krp::fuzz::asText(data + 1, size - 1);
  auto& folder = krp::fuzz::scratch();
  try {
    switch (data[0] % 3) {
      case 0: krp::readZonesYaml(folder.write("zones.yaml", text)); break;
      case 1: krp::readLandmarksYaml(folder.write("landmarks.yaml", text)); break;
      default: krp::readWorld(folder.write("world.yaml", text)); break;
    }
  } catch (const krp::InputError&) {
  }
  return 0;
}
