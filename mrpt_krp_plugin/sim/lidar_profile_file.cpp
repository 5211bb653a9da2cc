// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/sim/lidar_profile_file.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/yaml_file.h"

namespace krp {
namespace {

// What a file may ask for. Beyond these the simulator and the submap builder would be asked for
// something no 2D scanner produces, so a typo (max_range_m: 8000) is refused rather than trained on.
constexpr double kMaxFovDeg = 360.0;
constexpr int kMinBeams = 2;
constexpr int kMaxBeams = 100000;
constexpr double kMaxRangeM = 1000.0;
constexpr double kMaxNoiseStdM = 1.0;
constexpr double kMaxMountOffsetM = 10.0;

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

bool isLidarProfileFile(const std::string& name_or_file) {
  return endsWith(name_or_file, ".yaml") || endsWith(name_or_file, ".yml");
}

LidarProfile readLidarProfileFile(const std::string& path) {
  return readYamlFile(path, [&](const YAML::Node& root) {
    if (!root.IsMap()) throw InputError(path, "expected a YAML mapping of lidar settings");
    rejectUnknownYamlKeys(root,
                          {"name", "fov_deg", "beams", "max_range_m", "range_noise_std_m", "dropout_probability",
                           "mount_x_m"},
                          path);
    for (const char* required : {"fov_deg", "beams", "max_range_m"})
      if (!root[required]) throw InputError(path, std::string("missing required key '") + required + "'");
    LidarProfile p;
    p.name = root["name"] ? root["name"].as<std::string>() : std::filesystem::path(path).stem().string();
    if (p.name.empty()) throw InputError(path, "key 'name' is empty");
    p.fov_rad = yamlNumberInRange(root, "fov_deg", path, 0.0, kMaxFovDeg, true) * M_PI / 180.0;
    const double beams = yamlNumberInRange(root, "beams", path, kMinBeams, kMaxBeams);
    if (beams != std::floor(beams)) throw InputError(path, "key 'beams' must be a whole number");
    p.beams = static_cast<int>(beams);
    p.max_range_m = yamlNumberInRange(root, "max_range_m", path, 0.0, kMaxRangeM, true);
    if (root["range_noise_std_m"]) p.range_noise_std_m = yamlNumberInRange(root, "range_noise_std_m", path, 0.0, kMaxNoiseStdM);
    if (root["dropout_probability"]) p.dropout_probability = yamlNumberInRange(root, "dropout_probability", path, 0.0, 1.0);
    if (root["mount_x_m"]) p.mount_x_m = yamlNumberInRange(root, "mount_x_m", path, -kMaxMountOffsetM, kMaxMountOffsetM);
    return p;
  });
}

void writeLidarProfileFile(const LidarProfile& profile, const std::string& path) {
  std::ostringstream o;
  o.precision(17);
  o << "# Lidar profile (mrpt_krp_plugin, sim/lidar_profile_file.h)\n"
    << "name: " << profile.name << "\n"
    << "fov_deg: " << profile.fov_rad * 180.0 / M_PI << "\n"
    << "beams: " << profile.beams << "\n"
    << "max_range_m: " << profile.max_range_m << "\n"
    << "range_noise_std_m: " << profile.range_noise_std_m << "\n"
    << "dropout_probability: " << profile.dropout_probability << "\n"
    << "mount_x_m: " << profile.mount_x_m << "\n";
  writeFileAtomically(path, o.str());
}

LidarProfile lidarProfile(const std::string& name_or_file) {
  if (isLidarProfileFile(name_or_file)) return readLidarProfileFile(name_or_file);
  try {
    return lidarProfileByName(name_or_file);
  } catch (const InputError& e) {
    throw InputError(e.input(), e.problem() + "; or give a profile file, NAME.yaml (fov_deg, beams, max_range_m)");
  }
}

}  // namespace krp
