// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

/// Parses a YAML file. Throws InputError naming the file for a missing file ("file does not
/// exist") or a syntax error ("malformed YAML: ..."); every YAML input goes through here.
YAML::Node loadYamlFile(const std::string& path);

/// Parses a YAML file and runs `interpret` on its root. A YAML exception that `interpret` lets out
/// (a key looked up in a scalar, a list where a value was expected) becomes an InputError naming
/// the file, so that no reader can leak one however its own checks are written.
template <typename Interpret>
auto readYamlFile(const std::string& path, Interpret&& interpret) {
  const YAML::Node root = loadYamlFile(path);
  try {
    return interpret(root);
  } catch (const YAML::Exception& e) {
    throw InputError(path, "unexpected YAML structure: " + e.msg);
  }
}

/// Throws InputError(file, "[context: ]unknown key '<key_prefix><key>'") for the first key of
/// the mapping `node` that is not in `known`; every YAML reader checks its keys through here.
void rejectUnknownYamlKeys(const YAML::Node& node, const std::set<std::string>& known, const std::string& file,
                           const std::string& context = "", const std::string& key_prefix = "");

/// The number at `key` of the mapping `node`, which must lie in [lo, hi], or in (lo, hi] with
/// `exclude_lo`. Throws InputError(file, "key '<key>' is not a number") or
/// InputError(file, "key '<key>' = <v> is outside [lo, hi]") otherwise.
double yamlNumberInRange(const YAML::Node& node, const std::string& key, const std::string& file, double lo, double hi,
                         bool exclude_lo = false);

}  // namespace krp
