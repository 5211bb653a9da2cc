// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <mrpt/math/TPoint2D.h>

#include "mrpt_krp_plugin/submap/submap_params.h"

namespace krp {

/// How an 8-bit image becomes the model's float input: (value * scale - mean) / std.
struct InputNormalization {
  double scale = 1.0 / 255.0;
  double mean = 0.0;
  double std = 1.0;
};

/// One exported model as the manifest describes it.
struct ManifestModel {
  std::string file;    ///< relative to the manifest's folder
  std::string sha256;  ///< of the file, as exported
  std::string input_name;
  std::vector<int64_t> input_shape;
  std::string output_name;
  InputNormalization normalization;
};

/// manifest.json written by krp-train-map beside the two ONNX models: what they were trained
/// on (map, lidar, submap geometry, zones, landmarks), and how to feed them.
struct ModelManifest {
  std::string folder;  ///< where the manifest was read from
  std::string world;
  std::string lidar_name;
  double lidar_fov_deg = 0;
  double lidar_max_range_m = 0;
  double map_resolution_m = 0;  ///< cell size of the map trained on; 0 when not recorded (non-YAML maps)
  double submap_size_m = 0;
  int submap_size_px = 0;
  SubmapOrientation submap_orientation = SubmapOrientation::kHeadingUp;
  double sdt_clip_m = 0;
  std::vector<std::string> zones;
  /// The zones.yaml the models were trained on, beside them (the zone search reads it); empty in
  /// manifests written before krp-train-map copied it there.
  std::string zone_outlines_file;
  /// landmarks[z][k]: map coordinates of zone z's k-th keypoint [m]
  std::vector<std::vector<mrpt::math::TPoint2D>> landmarks;
  ManifestModel classifier;
  ManifestModel keypoints;

  int keypointsPerZone() const { return landmarks.empty() ? 0 : static_cast<int>(landmarks.front().size()); }
  std::string classifierPath() const { return folder + "/" + classifier.file; }
  std::string keypointsPath() const { return folder + "/" + keypoints.file; }
  std::string zoneOutlinesPath() const { return zone_outlines_file.empty() ? "" : folder + "/" + zone_outlines_file; }
};

/// Reads `<folder>/manifest.json`. InputError naming the file and the field for a missing file,
/// malformed JSON, a missing or mistyped field, or inconsistent contents (landmark zones that are
/// not the zone list, input shapes that are not the submap size).
ModelManifest readModelManifest(const std::string& folder);

/// The folder and the first digits of its two models' sha256 (checked against the files when the
/// models load): enough to tell two trainings apart in a report or a log.
std::string modelsIdentity(const ModelManifest& manifest);

}  // namespace krp
