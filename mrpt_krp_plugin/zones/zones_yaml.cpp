// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/zones/zones_yaml.h"

#include <yaml-cpp/yaml.h>

#include <set>
#include <sstream>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/yaml_file.h"
#include "mrpt_krp_plugin/zones/yaml_points.h"

namespace krp {

namespace {
std::vector<Zone> interpretZones(const YAML::Node& root, const std::string& path) {
  if (!root.IsMap() || !root["zones"]) throw InputError(path, "expected a top-level 'zones' list");
  rejectUnknownYamlKeys(root, {"zones"}, path);
  const auto list = root["zones"];
  if (!list.IsSequence()) throw InputError(path, "'zones' must be a list");
  std::vector<Zone> zones;
  std::set<std::string> names;
  for (size_t i = 0; i < list.size(); ++i) {
    const auto z = list[i];
    const std::string where = "zone #" + std::to_string(i);
    if (!z.IsMap()) throw InputError(path, where + " is not a mapping");
    rejectUnknownYamlKeys(z, {"name", "polygon"}, path, where);
    Zone zone;
    try {
      zone.name = z["name"].as<std::string>();
    } catch (const YAML::Exception&) {
      throw InputError(path, where + ": missing or invalid 'name'");
    }
    if (zone.name.empty()) throw InputError(path, where + ": empty name");
    if (!names.insert(zone.name).second) throw InputError(path, "zone name '" + zone.name + "' is used twice");
    // The zone's own name in errors; "polygon" says which list is wrong.
    zone.polygon = readYamlPoints(z["polygon"], path, "zone '" + zone.name + "' polygon", 3);
    zones.push_back(std::move(zone));
  }
  if (zones.empty()) throw InputError(path, "the zone list is empty");
  return zones;
}
}  // namespace

std::vector<Zone> readZonesYaml(const std::string& path) {
  return readYamlFile(path, [&](const YAML::Node& root) { return interpretZones(root, path); });
}

void writeZonesYaml(const std::vector<Zone>& zones, const std::string& path) {
  std::ostringstream o;
  o.precision(10);
  o << "# Zones in grid-frame metres. Written by mrpt_krp_plugin.\nzones:\n";
  for (const auto& z : zones) {
    o << "  - name: " << z.name << "\n    polygon: ";
    writeYamlPoints(o, z.polygon);
    o << "\n";
  }
  writeFileAtomically(path, o.str());
}

}  // namespace krp
