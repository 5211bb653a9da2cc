// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/dataset/keypoint_label.h"
#include "mrpt_krp_plugin/dataset/location_split.h"
#include "mrpt_krp_plugin/dataset/scenario.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/submap/sdt_image.h"
#include "mrpt_krp_plugin/submap/submap_params.h"
#include "mrpt_krp_plugin/zones/landmarks.h"

namespace krp {

struct DatasetParams {
  int samples_per_zone = 400;          ///< train + val + test poses per zone
  int changed_samples_per_zone = 60;   ///< extra poses per zone for the changed-environment split
  double wall_clearance_m = 0.3;       ///< sampled poses keep this far from mapped walls [m]
  int world_variants = 12;             ///< cluttered copies of the world the samples are drawn in
  int preview_per_zone = 4;            ///< samples per zone on the preview contact sheet
  ScenarioParams scenario;
  LocationSplit split;
  SubmapParams submap;
  SdtImageParams sdt;
  KeypointLabelParams label;
  uint64_t seed = 1;
};

/// What went in and how much came out: the source of the dataset card.
struct DatasetCard {
  std::string world;
  std::string lidar;
  std::vector<std::string> zones;
  /// counts[split][zone] for splits train, val, test, changed
  std::map<std::string, std::map<std::string, int>> counts;
  std::map<std::string, int> keypoint_objects;   ///< per split: images with a labelled object
  std::map<std::string, int> observed_keypoints; ///< per split: keypoints with visibility 2
};

/// Everything the generator needs about the place.
struct DatasetInputs {
  std::string world_name;
  const mrpt::maps::COccupancyGridMap2D* map = nullptr;
  std::vector<Zone> zones;
  std::vector<ZoneLandmarks> landmarks;  ///< one per zone, same order
  LandmarkParams landmark_params;
  ClutterParams clutter;
  LidarProfile lidar;
  /// The lidar came from the user's profile file, not a built-in name: models trained on the data
  /// need that file (written as lidar.yaml) to render fresh submaps of it.
  bool lidar_from_file = false;
};

/// Writes the dataset under `out_dir` (built in `out_dir.partial`, renamed when complete):
///   classifier/{train,val,test,changed}/<zone>/<id>.png     occupancy images
///   keypoints/images/{split}/<id>.png, keypoints/labels/{split}/<id>.txt   SDT images + YOLO-pose labels
///   keypoints/data.yaml, samples.csv, zones.yaml, landmarks.yaml, lidar.yaml (the simulated lidar's
///   profile), dataset_card.json, DATASET_CARD.md,
///   preview.png (a contact sheet of samples with their keypoints)
/// Progress goes to `progress`. Throws InputError for unusable inputs; an existing `out_dir`
/// is refused rather than overwritten.
DatasetCard generateDataset(const DatasetInputs& in, const DatasetParams& params, const std::string& out_dir,
                            std::ostream& progress);

}  // namespace krp
