// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/model_manifest.h"

#include <fstream>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

namespace {

using nlohmann::json;

const char* const kFormat = "mrpt_krp_plugin-models";
constexpr int kFormatVersion = 1;

// Looks up a dotted path and converts it, so every error names the field that is wrong.
template <typename T>
T field(const json& root, const std::string& dotted, const std::string& file) {
  const json* node = &root;
  size_t start = 0;
  while (true) {
    const size_t dot = dotted.find('.', start);
    const std::string key = dotted.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!node->is_object() || !node->contains(key)) throw InputError(file, "missing field '" + dotted + "'");
    node = &(*node)[key];
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  // nlohmann converts a float to an integer with a plain cast, undefined beyond the integer's
  // range (found by model_manifest_fuzzer): integers must be written as integers.
  const auto wrong_type = [&] { return InputError(file, "field '" + dotted + "' has the wrong type"); };
  if constexpr (std::is_integral_v<T>) {
    if (!node->is_number_integer()) throw wrong_type();
  }
  if constexpr (std::is_same_v<T, std::vector<int64_t>>) {
    if (!node->is_array()) throw wrong_type();
    for (const auto& e : *node)
      if (!e.is_number_integer()) throw wrong_type();
  }
  try {
    return node->get<T>();
  } catch (const json::exception&) {
    throw wrong_type();
  }
}

ManifestModel readModel(const json& root, const std::string& key, const std::string& file) {
  ManifestModel m;
  m.file = field<std::string>(root, key + ".file", file);
  m.sha256 = field<std::string>(root, key + ".sha256", file);
  m.input_name = field<std::string>(root, key + ".input.name", file);
  m.input_shape = field<std::vector<int64_t>>(root, key + ".input.shape", file);
  m.output_name = field<std::string>(root, key + ".output.name", file);
  m.normalization.scale = field<double>(root, key + ".input.normalize.scale", file);
  m.normalization.mean = field<double>(root, key + ".input.normalize.mean", file);
  m.normalization.std = field<double>(root, key + ".input.normalize.std", file);
  if (m.file.empty() || m.file.find('/') != std::string::npos)
    throw InputError(file, "'" + key + ".file' must be a file name in the manifest's folder");
  if (!(m.normalization.std > 0)) throw InputError(file, "'" + key + ".input.normalize.std' must be > 0");
  return m;
}

void checkImageShape(const ManifestModel& m, int channels, int size_px, const std::string& key,
                     const std::string& file) {
  const std::vector<int64_t> want{1, channels, size_px, size_px};
  if (m.input_shape != want)
    throw InputError(file, "'" + key + ".input.shape' does not match a " + std::to_string(channels) + " x " +
                               std::to_string(size_px) + " x " + std::to_string(size_px) + " submap image");
}

}  // namespace

ModelManifest readModelManifest(const std::string& folder) {
  const std::string file = folder + "/manifest.json";
  std::ifstream in(file);
  if (!in) throw InputError(file, "cannot open (is '" + folder + "' a folder written by krp-train-map?)");
  json root;
  try {
    root = json::parse(in);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number too large
    throw InputError(file, std::string("not valid JSON: ") + e.what());
  }
  if (field<std::string>(root, "format", file) != kFormat)
    throw InputError(file, std::string("'format' is not '") + kFormat + "'");
  if (field<int>(root, "format_version", file) != kFormatVersion)
    throw InputError(file, "format_version " + std::to_string(field<int>(root, "format_version", file)) +
                               " is not the supported " + std::to_string(kFormatVersion));
  ModelManifest m;
  m.folder = folder;
  m.world = field<std::string>(root, "world", file);
  m.lidar_name = field<std::string>(root, "lidar.name", file);
  m.lidar_fov_deg = field<double>(root, "lidar.fov_deg", file);
  m.lidar_max_range_m = field<double>(root, "lidar.max_range_m", file);
  if (root.contains("map") && root["map"].is_object() && root["map"].contains("resolution_m"))
    m.map_resolution_m = field<double>(root, "map.resolution_m", file);
  m.submap_size_m = field<double>(root, "submap.size_m", file);
  m.submap_size_px = field<int>(root, "submap.size_px", file);
  m.sdt_clip_m = field<double>(root, "sdt_clip_m", file);
  // Manifests written before wall-aligned submaps existed have no orientation: heading up.
  if (root.contains("submap") && root["submap"].is_object() && root["submap"].contains("orientation"))
    m.submap_orientation = parseOrientation(field<std::string>(root, "submap.orientation", file), file);
  m.zones = field<std::vector<std::string>>(root, "zones", file);
  if (!(m.submap_size_m > 0) || m.submap_size_px <= 0 || !(m.sdt_clip_m > 0))
    throw InputError(file, "submap size and sdt_clip_m must be positive");
  if (m.zones.empty()) throw InputError(file, "'zones' is empty");

  const auto zones = field<json>(root, "landmarks.zones", file);
  if (!zones.is_array() || zones.size() != m.zones.size())
    throw InputError(file, "'landmarks.zones' must list the " + std::to_string(m.zones.size()) + " zones");
  const int k = field<int>(root, "landmarks.keypoints_per_zone", file);
  for (size_t z = 0; z < zones.size(); ++z) {
    if (field<std::string>(zones[z], "zone", file) != m.zones[z])
      throw InputError(file, "landmarks zone " + std::to_string(z) + " is not '" + m.zones[z] + "'");
    const auto points = field<std::vector<std::vector<double>>>(zones[z], "points", file);
    if (static_cast<int>(points.size()) != k)
      throw InputError(file, "zone '" + m.zones[z] + "' has " + std::to_string(points.size()) + " landmarks, not " +
                                 std::to_string(k));
    std::vector<mrpt::math::TPoint2D> pts;
    for (const auto& p : points) {
      if (p.size() != 2) throw InputError(file, "a landmark of zone '" + m.zones[z] + "' is not [x, y]");
      pts.emplace_back(p[0], p[1]);
    }
    m.landmarks.push_back(std::move(pts));
  }
  if (root.contains("zone_outlines") && !root["zone_outlines"].is_null()) {
    m.zone_outlines_file = field<std::string>(root, "zone_outlines.file", file);
    if (m.zone_outlines_file.empty() || m.zone_outlines_file.find('/') != std::string::npos)
      throw InputError(file, "'zone_outlines.file' must be a file name in the manifest's folder");
  }
  m.classifier = readModel(root, "classifier", file);
  m.keypoints = readModel(root, "keypoints", file);
  checkImageShape(m.classifier, 1, m.submap_size_px, "classifier", file);
  checkImageShape(m.keypoints, 3, m.submap_size_px, "keypoints", file);
  return m;
}

std::string modelsIdentity(const ModelManifest& manifest) {
  constexpr size_t kDigits = 12;
  return manifest.folder + " (classifier sha256 " + manifest.classifier.sha256.substr(0, kDigits) +
         ", keypoints sha256 " + manifest.keypoints.sha256.substr(0, kDigits) + ")";
}

}  // namespace krp
