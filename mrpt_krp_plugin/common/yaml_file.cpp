// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/yaml_file.h"

#include <filesystem>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

YAML::Node loadYamlFile(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path, "file does not exist");
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw InputError(path, std::string("malformed YAML: ") + e.what());
  }
}

}  // namespace krp
