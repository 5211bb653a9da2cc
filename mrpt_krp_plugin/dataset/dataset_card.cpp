// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/dataset/dataset_card.h"

#include <nlohmann/json.hpp>
#include <sstream>

namespace krp {
namespace {
const char* const kSplits[] = {"train", "val", "test", "changed"};
}

std::string datasetCardJson(const DatasetCard& card, const DatasetParams& p, const DatasetInputs& in) {
  nlohmann::ordered_json j;
  j["world"] = card.world;
  j["lidar"] = {{"name", in.lidar.name},
                {"fov_deg", in.lidar.fov_rad * 180.0 / M_PI},
                {"beams", in.lidar.beams},
                {"max_range_m", in.lidar.max_range_m},
                {"range_noise_std_m", in.lidar.range_noise_std_m},
                {"dropout_probability", in.lidar.dropout_probability},
                {"mount_x_m", in.lidar.mount_x_m},
                {"from_file", in.lidar_from_file}};
  j["zones"] = card.zones;
  j["seed"] = p.seed;
  j["samples_per_zone"] = p.samples_per_zone;
  j["changed_samples_per_zone"] = p.changed_samples_per_zone;
  j["wall_clearance_m"] = p.wall_clearance_m;
  j["world_variants"] = p.world_variants;
  const auto& s = p.scenario;
  j["scenario"] = {{"strength", s.strength},
                   {"clutter_scale", s.clutter_scale},
                   {"occlusion_probability", s.occlusion_probability},
                   {"occlusion_max_sector_deg", s.occlusion_max_sector_deg},
                   {"extra_range_noise_m", s.extra_range_noise_m},
                   {"extra_dropout", s.extra_dropout},
                   {"changed_environment", "x3 clutter and occlusion, a third of the furniture moved"}};
  j["split"] = {{"by", "floor block"},
                {"block_m", p.split.block_m},
                {"seed", p.split.seed},
                {"train", p.split.train_fraction},
                {"val", p.split.val_fraction},
                {"test", 1.0 - p.split.train_fraction - p.split.val_fraction}};
  j["submap"] = {{"size_m", p.submap.size_m},
                 {"size_px", p.submap.size_px},
                 {"resolution_m", p.submap.resolutionM()},
                 {"no_return_free_fraction", p.submap.no_return_free_fraction},
                 {"orientation", orientationName(p.submap.orientation)}};
  j["sdt_clip_m"] = p.sdt.clip_m;
  j["landmarks"] = {{"method", LandmarkParams::method()}, {"keypoints_per_zone", in.landmark_params.keypoints_per_zone}};
  j["keypoint_label"] = {{"observed_radius_cells", p.label.observed_radius_cells},
                         {"box_margin_px", p.label.box_margin_px}};
  j["counts"] = card.counts;
  j["keypoint_objects"] = card.keypoint_objects;
  j["observed_keypoints"] = card.observed_keypoints;
  return j.dump(2) + "\n";
}

std::string datasetCardMarkdown(const DatasetCard& card, const DatasetParams& p, const DatasetInputs& in) {
  std::ostringstream o;
  o << "# Dataset card: " << card.world << " / " << in.lidar.name << "\n\n"
    << "Made by `krp-dataset` (seed " << p.seed << ", split seed " << p.split.seed << "). Submap " << p.submap.size_m << " m at " << p.submap.size_px
    << " px (" << p.submap.resolutionM() << " m/px); SDT clip " << p.sdt.clip_m << " m; scenario strength "
    << p.scenario.strength << "; " << in.landmark_params.keypoints_per_zone << " landmarks per zone ("
    << LandmarkParams::method() << "). Splits by " << p.split.block_m << " m floor blocks, "
    << p.split.train_fraction << " / " << p.split.val_fraction << " / "
    << 1.0 - p.split.train_fraction - p.split.val_fraction
    << " (train / val / test); `changed` is drawn separately with heavier clutter and moved furniture.\n\n"
    << "Lidar `" << in.lidar.name << "` (" << (in.lidar_from_file ? "the user's profile file" : "built-in") << ", `lidar.yaml`): "
    << in.lidar.fov_rad * 180.0 / M_PI << " deg, " << in.lidar.beams << " beams, " << in.lidar.max_range_m
    << " m, range noise " << in.lidar.range_noise_std_m << " m, dropout " << in.lidar.dropout_probability << ".\n\n"
    << "| zone |";
  for (const char* s : kSplits) o << " " << s << " |";
  o << "\n|---|";
  for (size_t i = 0; i < std::size(kSplits); ++i) o << "---|";
  o << "\n";
  for (const auto& z : card.zones) {
    o << "| " << z << " |";
    for (const char* s : kSplits) {
      const auto it = card.counts.find(s);
      o << " " << (it == card.counts.end() || !it->second.count(z) ? 0 : it->second.at(z)) << " |";
    }
    o << "\n";
  }
  o << "\nKeypoint images with a labelled object / observed keypoints, per split:";
  for (const char* s : kSplits) {
    const auto a = card.keypoint_objects.find(s), b = card.observed_keypoints.find(s);
    o << " " << s << " " << (a == card.keypoint_objects.end() ? 0 : a->second) << " / "
      << (b == card.observed_keypoints.end() ? 0 : b->second) << ";";
  }
  o << "\n";
  return o.str();
}

}  // namespace krp
