// SPDX-License-Identifier: BSD-3-Clause
// krp-dataset: simulated training data for the zone classifier and the keypoint model.
#include <filesystem>
#include <iostream>

#include "cli_args.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/dataset/dataset_generator.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/lidar_profile_file.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "mrpt_krp_plugin/zones/auto_zoning.h"
#include "mrpt_krp_plugin/zones/landmarks_yaml.h"
#include "mrpt_krp_plugin/zones/zone_validation.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

using krp::apps::CliArgs;

// The 360 deg, 12 m profile: what the shipped models and the benchmarks use.
static const char* const kMapDefaultLidar = "omni_12m";

static int run(int argc, char** argv) {
  CliArgs args("krp-dataset",
               "Simulates scans over every zone of a world with MRPT's lidar simulator and the thesis's scenario "
               "generation, builds submaps, and writes occupancy images in zone folders (classifier) and SDT images "
               "with YOLO-pose labels (keypoint model), split by floor block, plus a changed-environment split and a "
               "dataset card.",
               {{"world", "NAME|FILE", "world name under --world-dir, or a *.world.yaml", "office_two_zone"},
                {"world-dir", "DIR", "folder of the worlds", "sim_worlds"},
                {"map", "FILE", "a map instead of a world (.yaml, .gridmap[.gz], .bt/.ot), default clutter", ""},
                {"zones", "FILE", "zones.yaml for --map (default: automatic zoning)", ""},
                {"target-area", "M2", "automatic zoning for --map: target zone area", "80"},
                {"lidar", "NAME|FILE", "lidar profile: a built-in name (lds01, omni_12m, safety_270) or your scanner's "
                 "NAME.yaml (fov_deg, beams, max_range_m, ...; see sim/lidar_profile_file.h) (default: the world's "
                 "default; omni_12m for --map)", ""},
                {"out", "DIR", "dataset folder (must not exist)", "out/dataset"},
                {"samples-per-zone", "N", "train+val+test poses per zone", "400"},
                {"changed-per-zone", "N", "changed-environment poses per zone", "60"},
                {"strength", "S", "scenario generation strength (0 = off, as the thesis's 'without')", "1"},
                {"landmarks", "FILE", "landmarks.yaml to use (default: extracted from the map)", ""},
                {"keypoints", "K", "landmarks per zone when extracting", "12"},
                {"size-px", "N", "submap image side", "160"},
                {"size-m", "M", "submap side (0 = sized for the lidar)", "0"},
                {"sdt-clip-m", "M", "SDT normalization distance", "2"},
                {"orientation", "heading_up|wall_axes", "how submaps are turned: the robot's heading up, or the walls along the image axes", "wall_axes"},
                {"block-m", "M", "floor block side for the split", "2"},
                {"seed", "N", "seed (printed; the dataset is reproducible from it)", "1"},
                {"split-seed", "N",
                 "seed of the floor blocks' split (default: --seed); fresh samples for trained models keep the "
                 "models' split seed, so their test images lie only in blocks the models never trained on",
                 ""}});
  if (!args.parse(argc, argv)) return 0;
  krp::World world;
  if (args.has("map")) {
    // A user's own map: no world file, so the built-in profiles and default clutter apply.
    world.name = std::filesystem::path(args.get("map")).stem().string();
    world.map_path = args.get("map");
    world.zones_path = args.get("zones");
    world.default_lidar_profile = kMapDefaultLidar;
  } else {
    world = krp::readWorld(krp::apps::worldFilePath(args.get("world"), args.get("world-dir")));
  }
  const auto map = krp::loadOccupancyMap(world.map_path);
  krp::DatasetInputs in;
  in.world_name = world.name;
  in.map = map.grid.get();
  if (!world.zones_path.empty()) {
    in.zones = krp::readZonesYaml(world.zones_path);
    krp::validateZones(*map.grid, in.zones, world.zones_path);
  } else {
    krp::AutoZoningParams zp;
    zp.target_area_m2 = args.number("target-area");
    in.zones = krp::autoZone(*map.grid, zp);
    krp::validateZones(*map.grid, in.zones, "automatic zoning of " + world.map_path);
  }
  in.landmark_params.keypoints_per_zone = static_cast<int>(args.integer("keypoints"));
  if (args.has("landmarks")) {
    in.landmarks = krp::readLandmarksYaml(args.get("landmarks"));
    in.landmark_params.keypoints_per_zone = static_cast<int>(in.landmarks.front().points.size());
    for (size_t z = 0; z < in.zones.size(); ++z)
      if (z >= in.landmarks.size() || in.landmarks[z].zone != in.zones[z].name)
        throw krp::InputError(args.get("landmarks"), "zones do not match the world's zones in name and order");
  } else {
    in.landmarks = krp::extractLandmarks(*map.grid, in.zones, in.landmark_params);
  }
  in.clutter = world.clutter;
  const std::string lidar_name = args.has("lidar") ? args.get("lidar") : world.default_lidar_profile;
  in.lidar = args.has("map") ? krp::lidarProfile(lidar_name) : world.lidar(lidar_name);
  in.lidar_from_file = krp::isLidarProfileFile(lidar_name);

  krp::DatasetParams p;
  p.samples_per_zone = static_cast<int>(args.integer("samples-per-zone"));
  p.changed_samples_per_zone = static_cast<int>(args.integer("changed-per-zone"));
  p.scenario.strength = args.number("strength");
  p.submap = krp::submapParamsForLidar(in.lidar, static_cast<int>(args.integer("size-px")));
  const double size_m = args.number("size-m");
  if (size_m < 0) throw krp::InputError("--size-m", "'" + args.get("size-m") + "' is negative (0 = sized for the lidar)");
  if (size_m > 0) p.submap.size_m = size_m;
  p.submap.orientation = krp::parseOrientation(args.get("orientation"), "--orientation");
  p.sdt.clip_m = args.number("sdt-clip-m");
  p.split.block_m = args.number("block-m");
  p.seed = args.seed("seed");
  p.split.seed = args.has("split-seed") ? args.seed("split-seed") : p.seed;
  std::cerr << "krp-dataset: world " << world.name << ", lidar " << in.lidar.name << ", " << in.zones.size()
            << " zones, seed " << p.seed << ", submap " << p.submap.size_m << " m / " << p.submap.size_px << " px, "
            << krp::orientationName(p.submap.orientation) << "\n";
  const auto card = krp::generateDataset(in, p, args.get("out"), std::cerr);
  for (const auto& [split, zones] : card.counts) {
    int total = 0;
    for (const auto& [z, n] : zones) total += n;
    std::cout << split << ": " << total << " images\n";
  }
  std::cout << "dataset: " << args.get("out") << " (DATASET_CARD.md)\n";
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-dataset", run, argc, argv); }
