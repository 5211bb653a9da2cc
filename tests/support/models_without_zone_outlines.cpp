// SPDX-License-Identifier: BSD-3-Clause
#include "support/models_without_zone_outlines.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/test_maps.h"

namespace krp::test {

std::string modelsWithoutZoneOutlines(const std::string& name) {
  const std::filesystem::path dir = tempDir(name);
  std::filesystem::copy(std::string(KRP_SOURCE_DIR) + "/models/office_two_zone", dir,
                        std::filesystem::copy_options::recursive);
  std::filesystem::remove(dir / "zones.yaml");
  nlohmann::json manifest = nlohmann::json::parse(std::ifstream(dir / "manifest.json"));
  manifest.erase("zone_outlines");
  std::ofstream(dir / "manifest.json") << manifest.dump();
  return dir.string();
}

}  // namespace krp::test
