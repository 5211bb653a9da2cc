// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>

namespace krp {

/// Parses a YAML file. Throws InputError naming the file for a missing file ("file does not
/// exist") or a syntax error ("malformed YAML: ..."); every YAML input goes through here.
YAML::Node loadYamlFile(const std::string& path);

/// Throws InputError(file, "[context: ]unknown key '<key_prefix><key>'") for the first key of
/// the mapping `node` that is not in `known`; every YAML reader checks its keys through here.
void rejectUnknownYamlKeys(const YAML::Node& node, const std::set<std::string>& known, const std::string& file,
                           const std::string& context = "", const std::string& key_prefix = "");

}  // namespace krp
