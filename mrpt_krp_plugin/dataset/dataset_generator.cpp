// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/dataset/dataset_generator.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/png_file.h"
#include "mrpt_krp_plugin/common/progress_bar.h"
#include "mrpt_krp_plugin/dataset/dataset_card.h"
#include "mrpt_krp_plugin/sim/lidar_profile_file.h"
#include "mrpt_krp_plugin/dataset/dataset_preview.h"
#include "mrpt_krp_plugin/dataset/zone_pose_sampler.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/submap/occupancy_image.h"
#include "mrpt_krp_plugin/submap/submap_builder.h"
#include "mrpt_krp_plugin/submap/wall_axes.h"
#include "mrpt_krp_plugin/zones/landmarks_yaml.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

namespace fs = std::filesystem;

namespace krp {
namespace {

// Seed streams, so that the variant pools and the per-sample draws never share a stream.
constexpr uint64_t kVariantStream = 0x5641524941ull;
constexpr uint64_t kChangedVariantStream = 0x4348414e47ull;
constexpr uint64_t kSampleStream = 0x53414d50ull;
constexpr const char* kChangedSplit = "changed";

std::vector<mrpt::maps::COccupancyGridMap2D> worldVariants(const DatasetInputs& in, const ScenarioParams& scenario,
                                                           int count, uint64_t seed) {
  std::vector<mrpt::maps::COccupancyGridMap2D> out;
  for (int v = 0; v < count; ++v) {
    Rng rng(deriveSeed(seed, static_cast<uint64_t>(v)));
    out.push_back(scenarioWorld(*in.map, in.clutter, scenario, rng));
  }
  return out;
}

std::string ultralyticsDataYaml(const fs::path& keypoint_dir, const DatasetInputs& in) {
  std::ostringstream o;
  const int k = in.landmark_params.keypoints_per_zone;
  // ultralytics resolves relative paths against its own settings folder, so the path is absolute.
  o << "# ultralytics YOLO-pose dataset, written by krp-dataset\npath: " << fs::absolute(keypoint_dir).string()
    << "\ntrain: images/train\nval: images/val\ntest: images/test\nkpt_shape: [" << k << ", 3]\n"
    << "# Mirroring a submap does not permute landmarks; training keeps fliplr at 0.\nflip_idx: [";
  for (int i = 0; i < k; ++i) o << (i ? ", " : "") << i;
  o << "]\nnames:\n";
  for (size_t z = 0; z < in.zones.size(); ++z) o << "  " << z << ": " << in.zones[z].name << "\n";
  return o.str();
}

}  // namespace

DatasetCard generateDataset(const DatasetInputs& in, const DatasetParams& p, const std::string& out_dir,
                            std::ostream& progress) {
  if (!in.map) throw InputError("dataset generator", "no map");
  if (in.zones.empty()) throw InputError("dataset generator", "no zones");
  if (in.landmarks.size() != in.zones.size())
    throw InputError("dataset generator", "landmarks list " + std::to_string(in.landmarks.size()) + " zones, the map " +
                                              std::to_string(in.zones.size()));
  if (p.samples_per_zone < 1 || p.changed_samples_per_zone < 0 || p.world_variants < 1)
    throw InputError("dataset parameters", "samples_per_zone >= 1, changed_samples_per_zone >= 0, world_variants >= 1");
  if (!(p.split.block_m > 0.0) || !std::isfinite(p.split.block_m))
    throw InputError("dataset parameters", "the split's block_m must be a positive number of metres");
  if (!(p.scenario.strength >= 0.0) || !std::isfinite(p.scenario.strength))
    throw InputError("dataset parameters", "scenario strength must be 0 (off) or more");
  validateSubmapParams(p.submap);
  if (fs::exists(out_dir)) throw InputError(out_dir, "already exists; choose a new folder or remove it first");
  const fs::path partial = out_dir + ".partial";
  fs::remove_all(partial);

  const ZonePoseSampler sampler(*in.map, in.zones, p.wall_clearance_m);
  const ScenarioParams changed = p.scenario.changedEnvironment();
  const auto variants = worldVariants(in, p.scenario, p.world_variants, deriveSeed(p.seed, kVariantStream));
  const auto changed_variants = worldVariants(in, changed, p.world_variants, deriveSeed(p.seed, kChangedVariantStream));
  const ScanSimulator sim(scenarioLidar(in.lidar, p.scenario)), changed_sim(scenarioLidar(in.lidar, changed));

  DatasetCard card;
  card.world = in.world_name;
  card.lidar = in.lidar.name;
  for (const auto& z : in.zones) card.zones.push_back(z.name);
  std::ostringstream samples_csv;
  samples_csv << "id,split,zone,x_m,y_m,phi_rad,image_heading_rad,block,world_variant,occluded,hits,keypoints_inside,"
                 "keypoints_observed\n";
  // Wall-aligned submaps are drawn at the candidate the relocalizer would find right: the robot's
  // heading relative to the map's wall axes, as near as the scan's own wall estimate allows.
  const double map_axis_rad = mapWallAxes(*in.map).angle_rad;

  DatasetPreview preview(p.preview_per_zone);
  const int per_zone = p.samples_per_zone + p.changed_samples_per_zone;
  ProgressBar bar("dataset", in.zones.size() * static_cast<size_t>(per_zone), progress);
  for (size_t z = 0; z < in.zones.size(); ++z) {
    for (int i = 0; i < per_zone; ++i) {
      const bool is_changed = i >= p.samples_per_zone;
      Rng rng(deriveSeed(deriveSeed(p.seed, kSampleStream), z * 1000003ull + static_cast<uint64_t>(i)));
      const auto pose = sampler.sample(z, rng);
      const std::string split = is_changed ? kChangedSplit : splitName(p.split.of({pose.x(), pose.y()}));
      const int variant = rng.uniformInt(0, p.world_variants - 1);
      const auto& world = is_changed ? changed_variants[variant] : variants[variant];
      auto scan = (is_changed ? changed_sim : sim).simulate(world, pose, rng);
      const bool occluded = applyOcclusion(*scan, is_changed ? changed : p.scenario, rng);
      const double image_heading =
          nearestHeading(submapImageHeadings(*scan, p.submap),
                         p.submap.orientation == SubmapOrientation::kWallAxes ? pose.phi() - map_axis_rad : kHeadingUpRad);
      const Submap sub = buildSubmap(*scan, p.submap, image_heading);

      char id[48];
      std::snprintf(id, sizeof(id), "z%02zu_%05d", z, i);
      const cv::Mat occupancy_image = renderOccupancyImage(sub.grid), sdt_image = renderSdtImage(sub.grid, p.sdt);
      writePngAtomically((partial / "classifier" / split / in.zones[z].name / (std::string(id) + ".png")).string(),
                         occupancy_image);
      writePngAtomically((partial / "keypoints" / "images" / split / (std::string(id) + ".png")).string(), sdt_image);
      const auto keypoints = projectLandmarks(in.landmarks[z], pose, sub.grid, p.label);
      if (!is_changed) preview.add(z, occupancy_image, sdt_image, keypoints);
      const auto label = yoloPoseLabel(static_cast<int>(z), keypoints, p.submap.size_px, p.label);
      writeFileAtomically((partial / "keypoints" / "labels" / split / (std::string(id) + ".txt")).string(),
                          label ? *label + "\n" : "");
      int inside = 0, observed = 0;
      for (const auto& k : keypoints) {
        inside += k.visibility != KeypointVisibility::kOutside;
        observed += k.visibility == KeypointVisibility::kObserved;
      }
      ++card.counts[split][in.zones[z].name];
      card.keypoint_objects[split] += label ? 1 : 0;
      card.observed_keypoints[split] += observed;
      samples_csv << id << "," << split << "," << in.zones[z].name << "," << pose.x() << "," << pose.y() << ","
                  << pose.phi() << "," << image_heading << "," << p.split.blockId({pose.x(), pose.y()}) << "," << variant << ","
                  << (occluded ? 1 : 0) << "," << sub.hits << "," << inside << "," << observed << "\n";
      bar.advance(1, in.zones[z].name);
    }
  }
  bar.finish();

  writeFileAtomically((partial / "samples.csv").string(), samples_csv.str());
  preview.write((partial / "preview.png").string());
  writeZonesYaml(in.zones, (partial / "zones.yaml").string());
  writeLandmarksYaml(in.landmarks, in.landmark_params, (partial / "landmarks.yaml").string());
  writeLidarProfileFile(in.lidar, (partial / "lidar.yaml").string());
  writeFileAtomically((partial / "keypoints" / "data.yaml").string(), ultralyticsDataYaml(fs::path(out_dir) / "keypoints", in));
  writeFileAtomically((partial / "dataset_card.json").string(), datasetCardJson(card, p, in));
  writeFileAtomically((partial / "DATASET_CARD.md").string(), datasetCardMarkdown(card, p, in));
  fs::rename(partial, out_dir);
  return card;
}

}  // namespace krp
