// SPDX-License-Identifier: BSD-3-Clause
// krp-make-worlds: writes the project's simulated worlds (map, zones, world file, picture).
#include <filesystem>
#include <iostream>

#include "cli_args.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/map/ros_map_yaml.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "mrpt_krp_plugin/sim/world_builders.h"
#include "mrpt_krp_plugin/zones/zone_drawing.h"
#include "mrpt_krp_plugin/zones/zone_validation.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

namespace fs = std::filesystem;
using krp::apps::CliArgs;

static int run(int argc, char** argv) {
  CliArgs args("krp-make-worlds", "Generates the simulated worlds deterministically from a seed.",
               {{"out", "DIR", "output folder", "sim_worlds"},
                {"worlds", "A,B", "worlds to build", "office_two_zone,warehouse,large_floor"},
                {"seed", "N", "generator seed", "1"}});
  if (!args.parse(argc, argv)) return 0;
  for (const auto& name : args.list("worlds")) {
    const auto built = krp::buildWorld(name, args.seed("seed"));
    const fs::path dir = fs::path(args.get("out")) / name;
    krp::validateZones(built.map, built.zones, name + " (generated)");
    krp::writeRosMap(built.map, (dir / (name + ".yaml")).string());
    krp::writeZonesYaml(built.zones, (dir / (name + ".zones.yaml")).string());
    krp::writeZonesPng(built.map, built.zones, (dir / (name + ".zones.png")).string());
    krp::World w;
    w.name = name;
    w.map_path = (dir / (name + ".yaml")).string();
    w.zones_path = (dir / (name + ".zones.yaml")).string();
    w.lidar_profiles = {"omni_12m", "lds01", "safety_270"};
    w.default_lidar_profile = "omni_12m";
    if (name == "warehouse") w.clutter.pallets_per_100m2 = 0.5;  // a warehouse floor holds more pallets
    w.trial_start_zone = built.trial_start_zone;
    krp::writeWorld(w, (dir / (name + ".world.yaml")).string());
    std::cout << name << ": " << built.map.getSizeX() << " x " << built.map.getSizeY() << " cells, "
              << krp::freeAreaM2(built.map) << " m^2 free, " << built.zones.size() << " zones -> " << dir.string() << "\n";
  }
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-make-worlds", run, argc, argv); }
