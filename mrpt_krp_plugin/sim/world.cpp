// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/sim/world.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/yaml_file.h"
#include "mrpt_krp_plugin/sim/lidar_profile_file.h"

namespace fs = std::filesystem;

namespace krp {
namespace {
/// The same profile: the same name, or the same file however its path is written.
bool sameProfile(const std::string& a, const std::string& b) {
  if (a == b) return true;
  if (!isLidarProfileFile(a) || !isLidarProfileFile(b)) return false;
  std::error_code ea, eb;
  const auto ca = fs::weakly_canonical(a, ea), cb = fs::weakly_canonical(b, eb);
  return !ea && !eb && ca == cb;
}

/// A profile file named relative to the world file is found beside it, as the map is.
std::string besideWorld(const std::string& profile, const fs::path& dir) {
  return isLidarProfileFile(profile) && fs::path(profile).is_relative() ? (dir / profile).string() : profile;
}

/// How writeWorld names a profile: a file relative to the world's folder, as it names the map.
std::string relativeToWorld(const std::string& profile, const fs::path& dir) {
  return isLidarProfileFile(profile) ? fs::relative(profile, dir).string() : profile;
}
}  // namespace

LidarProfile World::lidar(const std::string& profile_name) const {
  const auto listed = std::find_if(lidar_profiles.begin(), lidar_profiles.end(),
                                   [&](const std::string& p) { return sameProfile(p, profile_name); });
  if (listed == lidar_profiles.end())
    throw InputError("world '" + name + "'", "lidar profile '" + profile_name + "' is not listed for this world");
  LidarProfile p = lidarProfile(*listed);
  if (range_noise_std_m >= 0) p.range_noise_std_m = range_noise_std_m;
  if (dropout_probability >= 0) p.dropout_probability = dropout_probability;
  return p;
}

LidarProfile World::lidarOrProfileFile(const std::string& name_or_file) const {
  return isLidarProfileFile(name_or_file) ? lidarProfile(name_or_file) : lidar(name_or_file);
}

namespace {
World interpretWorld(const YAML::Node& root, const std::string& path) {
  if (!root.IsMap()) throw InputError(path, "expected a YAML mapping");
  rejectUnknownYamlKeys(root,
                        {"name", "map", "zones", "lidar_profiles", "default_lidar_profile", "lidar_overrides", "clutter",
                         "trial_start_zone"},
                        path);
  for (const char* req : {"name", "map", "zones", "lidar_profiles"})
    if (!root[req]) throw InputError(path, std::string("missing required key '") + req + "'");
  const fs::path dir = fs::path(path).parent_path();
  World w;
  try {
    w.name = root["name"].as<std::string>();
    w.map_path = (dir / root["map"].as<std::string>()).string();
    w.zones_path = (dir / root["zones"].as<std::string>()).string();
    w.lidar_profiles = root["lidar_profiles"].as<std::vector<std::string>>();
  } catch (const YAML::Exception& e) {
    throw InputError(path, std::string("bad value: ") + e.what());
  }
  if (w.lidar_profiles.empty()) throw InputError(path, "'lidar_profiles' is empty");
  for (auto& p : w.lidar_profiles) p = besideWorld(p, dir);
  for (const auto& p : w.lidar_profiles) lidarProfile(p);  // throws for an unknown name or a bad file
  w.default_lidar_profile = root["default_lidar_profile"]
                                ? besideWorld(root["default_lidar_profile"].as<std::string>(), dir)
                                : w.lidar_profiles.front();
  if (std::find(w.lidar_profiles.begin(), w.lidar_profiles.end(), w.default_lidar_profile) == w.lidar_profiles.end())
    throw InputError(path, "default_lidar_profile '" + w.default_lidar_profile + "' is not in lidar_profiles");
  if (const auto o = root["lidar_overrides"]) {
    rejectUnknownYamlKeys(o, {"range_noise_std_m", "dropout_probability"}, path, "", "lidar_overrides.");
    if (o["range_noise_std_m"]) w.range_noise_std_m = yamlNumberInRange(o, "range_noise_std_m", path, 0.0, 1.0);
    if (o["dropout_probability"]) w.dropout_probability = yamlNumberInRange(o, "dropout_probability", path, 0.0, 1.0);
  }
  if (const auto c = root["clutter"]) {
    rejectUnknownYamlKeys(c,
                          {"boxes_per_100m2", "box_min_side_m", "box_max_side_m", "pallets_per_100m2",
                           "people_per_100m2", "placement_clearance_m"},
                          path, "", "clutter.");
    auto& k = w.clutter;
    if (c["boxes_per_100m2"]) k.boxes_per_100m2 = yamlNumberInRange(c, "boxes_per_100m2", path, 0.0, 100.0);
    if (c["box_min_side_m"]) k.box_min_side_m = yamlNumberInRange(c, "box_min_side_m", path, 0.01, 10.0);
    if (c["box_max_side_m"]) k.box_max_side_m = yamlNumberInRange(c, "box_max_side_m", path, 0.01, 10.0);
    if (c["pallets_per_100m2"]) k.pallets_per_100m2 = yamlNumberInRange(c, "pallets_per_100m2", path, 0.0, 100.0);
    if (c["people_per_100m2"]) k.people_per_100m2 = yamlNumberInRange(c, "people_per_100m2", path, 0.0, 100.0);
    if (c["placement_clearance_m"]) k.placement_clearance_m = yamlNumberInRange(c, "placement_clearance_m", path, 0.0, 10.0);
    if (k.box_min_side_m > k.box_max_side_m) throw InputError(path, "clutter.box_min_side_m > clutter.box_max_side_m");
  }
  if (const auto z = root["trial_start_zone"]) {
    try {
      w.trial_start_zone = z.as<std::string>();
    } catch (const YAML::Exception&) {
      throw InputError(path, "key 'trial_start_zone' is not a zone name");
    }
    if (w.trial_start_zone.empty()) throw InputError(path, "key 'trial_start_zone' is empty");
  }
  return w;
}
}  // namespace

World readWorld(const std::string& path) {
  return readYamlFile(path, [&](const YAML::Node& root) { return interpretWorld(root, path); });
}

void writeWorld(const World& w, const std::string& path) {
  const fs::path dir = fs::path(path).parent_path();
  std::ostringstream o;
  o << "# Simulated world for mrpt_krp_plugin (written by krp-make-worlds; see the README, section 'Sim worlds')\n"
    << "name: " << w.name << "\nmap: " << fs::relative(w.map_path, dir).string()
    << "\nzones: " << fs::relative(w.zones_path, dir).string() << "\nlidar_profiles: [";
  for (size_t i = 0; i < w.lidar_profiles.size(); ++i) o << (i ? ", " : "") << relativeToWorld(w.lidar_profiles[i], dir);
  o << "]\ndefault_lidar_profile: " << relativeToWorld(w.default_lidar_profile, dir) << "\n";
  if (w.range_noise_std_m >= 0 || w.dropout_probability >= 0) {
    o << "lidar_overrides:\n";
    if (w.range_noise_std_m >= 0) o << "  range_noise_std_m: " << w.range_noise_std_m << "\n";
    if (w.dropout_probability >= 0) o << "  dropout_probability: " << w.dropout_probability << "\n";
  }
  const auto& c = w.clutter;
  o << "clutter:\n  boxes_per_100m2: " << c.boxes_per_100m2 << "\n  box_min_side_m: " << c.box_min_side_m
    << "\n  box_max_side_m: " << c.box_max_side_m << "\n  pallets_per_100m2: " << c.pallets_per_100m2
    << "\n  people_per_100m2: " << c.people_per_100m2 << "\n  placement_clearance_m: " << c.placement_clearance_m
    << "\n";
  if (!w.trial_start_zone.empty()) o << "trial_start_zone: " << w.trial_start_zone << "\n";
  writeFileAtomically(path, o.str());
}

}  // namespace krp
