// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/zones/landmarks_yaml.h"

#include <set>
#include <sstream>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/yaml_file.h"
#include "mrpt_krp_plugin/zones/yaml_points.h"

namespace krp {

void writeLandmarksYaml(const std::vector<ZoneLandmarks>& landmarks, const LandmarkParams& p, const std::string& path) {
  std::ostringstream o;
  o.precision(10);
  o << "# Landmarks (keypoints) per zone, grid-frame metres. Written by mrpt_krp_plugin.\n"
    << "method: " << LandmarkParams::method() << "\nkeypoints_per_zone: " << p.keypoints_per_zone
    << "\nparameters: {search_margin_m: " << p.search_margin_m << ", min_spacing_m: " << p.min_spacing_m
    << ", corner_quality: " << p.corner_quality << ", corner_block_px: " << p.corner_block_px
    << ", wall_smoothing_m: " << p.wall_smoothing_m << "}\nzones:\n";
  for (const auto& z : landmarks) {
    o << "  - zone: " << z.zone << "\n    points: ";
    writeYamlPoints(o, z.points);
    o << "\n";
  }
  writeFileAtomically(path, o.str());
}

namespace {
std::vector<ZoneLandmarks> interpretLandmarks(const YAML::Node& root, const std::string& path) {
  if (!root.IsMap()) throw InputError(path, "expected a mapping with 'keypoints_per_zone' and 'zones'");
  rejectUnknownYamlKeys(root, {"method", "keypoints_per_zone", "parameters", "zones"}, path);
  int k = 0;
  try {
    k = root["keypoints_per_zone"].as<int>();
  } catch (const YAML::Exception&) {
    throw InputError(path, "missing or invalid 'keypoints_per_zone'");
  }
  if (k < 3) throw InputError(path, "keypoints_per_zone must be at least 3");
  const auto list = root["zones"];
  if (!list || !list.IsSequence() || list.size() == 0) throw InputError(path, "'zones' must be a non-empty list");
  std::vector<ZoneLandmarks> out;
  std::set<std::string> names;
  for (size_t i = 0; i < list.size(); ++i) {
    const auto z = list[i];
    if (!z.IsMap() || !z["zone"]) throw InputError(path, "entry #" + std::to_string(i) + " has no 'zone'");
    ZoneLandmarks zl;
    zl.zone = z["zone"].as<std::string>();
    if (!names.insert(zl.zone).second) throw InputError(path, "zone '" + zl.zone + "' is listed twice");
    zl.points = readYamlPoints(z["points"], path, "landmarks of zone '" + zl.zone + "'", static_cast<size_t>(k));
    if (zl.points.size() != static_cast<size_t>(k))
      throw InputError(path, "zone '" + zl.zone + "' has " + std::to_string(zl.points.size()) + " points, expected " +
                                 std::to_string(k));
    out.push_back(std::move(zl));
  }
  return out;
}
}  // namespace

std::vector<ZoneLandmarks> readLandmarksYaml(const std::string& path) {
  return readYamlFile(path, [&](const YAML::Node& root) { return interpretLandmarks(root, path); });
}

}  // namespace krp
