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

void rejectUnknownYamlKeys(const YAML::Node& node, const std::set<std::string>& known, const std::string& file,
                           const std::string& context, const std::string& key_prefix) {
  for (const auto& kv : node) {
    const auto key = kv.first.as<std::string>();
    if (!known.count(key))
      throw InputError(file, (context.empty() ? "" : context + ": ") + "unknown key '" + key_prefix + key + "'");
  }
}

}  // namespace krp
