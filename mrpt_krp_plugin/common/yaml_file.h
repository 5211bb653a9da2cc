// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace krp {

/// Parses a YAML file. Throws InputError naming the file for a missing file ("file does not
/// exist") or a syntax error ("malformed YAML: ..."); every YAML input goes through here.
YAML::Node loadYamlFile(const std::string& path);

}  // namespace krp
