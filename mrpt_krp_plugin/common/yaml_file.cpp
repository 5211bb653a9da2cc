// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/yaml_file.h"

#include <filesystem>
#include <sstream>

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

double yamlNumberInRange(const YAML::Node& node, const std::string& key, const std::string& file, double lo, double hi,
                         bool exclude_lo) {
  double v = 0.0;
  try {
    v = node[key].as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(file, "key '" + key + "' is not a number");
  }
  const bool above_lo = exclude_lo ? v > lo : v >= lo;
  if (!(above_lo && v <= hi)) {
    std::ostringstream s;
    s << "key '" << key << "' = " << v << " is outside " << (exclude_lo ? "(" : "[") << lo << ", " << hi << "]";
    throw InputError(file, s.str());
  }
  return v;
}

}  // namespace krp
