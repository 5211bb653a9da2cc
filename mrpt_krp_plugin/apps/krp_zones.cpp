// SPDX-License-Identifier: BSD-3-Clause
// krp-zones: loads a map, validates given zones or zones it automatically, draws them.
#include <iostream>

#include "cli_args.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/zones/auto_zoning.h"
#include "mrpt_krp_plugin/zones/landmark_drawing.h"
#include "mrpt_krp_plugin/zones/landmarks_yaml.h"
#include "mrpt_krp_plugin/zones/zone_drawing.h"
#include "mrpt_krp_plugin/zones/zone_validation.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

using krp::apps::CliArgs;

static int run(int argc, char** argv) {
  CliArgs args("krp-zones",
               "Loads a map (.yaml, .gridmap[.gz], .bt/.ot), then validates --zones or zones it automatically, "
               "and writes the zones as YAML and a labelled PNG; optionally extracts each zone's landmarks.",
               {{"map", "FILE", "map file (required)", ""},
                {"zones", "FILE", "zones.yaml to validate (otherwise: automatic zoning)", ""},
                {"target-area", "M2", "automatic zoning: target zone area", "80"},
                {"out-yaml", "FILE", "where to write the zones (automatic zoning)", ""},
                {"out-png", "FILE", "where to write the picture", ""},
                {"landmarks-yaml", "FILE", "also extract K landmarks per zone and write them here", ""},
                {"landmarks-png", "FILE", "picture of the zones with their numbered landmarks", ""},
                {"keypoints", "K", "landmarks per zone", "12"},
                {"octomap-z-min", "M", "OctoMap slice: lower height", "0.05"},
                {"octomap-z-max", "M", "OctoMap slice: upper height", "0.6"}});
  if (!args.parse(argc, argv)) return 0;
  if (args.get("map").empty()) throw krp::InputError("--map", "is required\n" + args.usage());
  krp::MapLoadParams lp;
  lp.octomap.z_min_m = args.number("octomap-z-min");
  lp.octomap.z_max_m = args.number("octomap-z-max");
  const auto map = krp::loadOccupancyMap(args.get("map"), lp);
  const auto& g = *map.grid;
  std::cout << "map " << map.source << ": " << g.getSizeX() << " x " << g.getSizeY() << " cells at " << g.getResolution()
            << " m, x [" << g.getXMin() << ", " << g.getXMax() << "], y [" << g.getYMin() << ", " << g.getYMax()
            << "], free " << krp::freeAreaM2(g) << " m^2\n";
  std::vector<krp::Zone> zones;
  if (args.has("zones")) {
    zones = krp::readZonesYaml(args.get("zones"));
    krp::validateZones(g, zones, args.get("zones"));
    std::cout << zones.size() << " zones: valid\n";
  } else {
    krp::AutoZoningParams zp;
    zp.target_area_m2 = args.number("target-area");
    zones = krp::autoZone(g, zp);
    krp::validateZones(g, zones, "automatic zoning");
    std::cout << zones.size() << " zones from automatic zoning (target " << zp.target_area_m2 << " m^2): valid\n";
    if (args.has("out-yaml")) krp::writeZonesYaml(zones, args.get("out-yaml"));
  }
  for (const auto& z : zones) std::cout << "  " << z.name << ": " << krp::polygonAreaM2(z.polygon) << " m^2 outline\n";
  if (args.has("out-png")) {
    krp::writeZonesPng(g, zones, args.get("out-png"));
    std::cout << "picture: " << args.get("out-png") << "\n";
  }
  if (args.has("landmarks-yaml") || args.has("landmarks-png")) {
    krp::LandmarkParams lmp;
    lmp.keypoints_per_zone = static_cast<int>(args.number("keypoints"));
    const auto landmarks = krp::extractLandmarks(g, zones, lmp);
    std::cout << lmp.keypoints_per_zone << " landmarks per zone (" << krp::LandmarkParams::method() << ")\n";
    if (args.has("landmarks-yaml")) krp::writeLandmarksYaml(landmarks, lmp, args.get("landmarks-yaml"));
    if (args.has("landmarks-png")) krp::writeLandmarksPng(g, zones, landmarks, args.get("landmarks-png"));
  }
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-zones", run, argc, argv); }
