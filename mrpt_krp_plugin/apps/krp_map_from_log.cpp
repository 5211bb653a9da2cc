// SPDX-License-Identifier: BSD-3-Clause
// krp-map-from-log: an occupancy map (map_server YAML + PGM) from a SLAM-corrected CARMEN log's
// scans at its poses; a subset of the scans (--first, --every) leaves the others out to be
// relocalized against a map that never saw them.
#include <iostream>

#include "cli_args.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/logs/carmen_log.h"
#include "mrpt_krp_plugin/logs/log_mapper.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/map/ros_map_yaml.h"

using krp::apps::CliArgs;

static int run(int argc, char** argv) {
  CliArgs args("krp-map-from-log",
               "Builds an occupancy map from the scans of a SLAM-corrected CARMEN log at the poses it states "
               "(MRPT ray insertion) and writes it as a map_server YAML + PGM.",
               {{"carmen", "FILE", "CARMEN log (.log or .log.gz) whose poses are corrected (required)", ""},
                {"carmen-fov-deg", "DEG", "field of view of FLASER lines (they state none)", "180"},
                {"out", "FILE", "map YAML to write; the PGM goes beside it (required)", ""},
                {"resolution", "M", "cell size", "0.05"},
                {"max-range", "M", "rays are inserted up to this range", "30"},
                {"first", "N", "first scan used", "0"},
                {"every", "N", "then every N-th scan", "1"}});
  if (!args.parse(argc, argv)) return 0;
  if (args.get("carmen").empty() || args.get("out").empty())
    throw krp::InputError("arguments", "--carmen and --out are required\n" + args.usage());
  krp::CarmenLogParams cp;
  cp.flaser_fov_deg = args.number("carmen-fov-deg");
  const auto log = krp::readCarmenLog(args.get("carmen"), cp);
  if (log.poses_from_odom_lines)
    throw krp::InputError(args.get("carmen"), "has no FLASER or ROBOTLASER1 line: the poses of its RAWLASER1 scans are "
                                              "the ODOM lines' odometry, and a map needs corrected ones");
  krp::LogMapperParams mp;
  mp.resolution_m = args.number("resolution");
  mp.max_insertion_range_m = args.number("max-range");
  const long long first = args.integer("first"), every = args.integer("every");
  if (first < 0) throw krp::InputError("--first", "must be >= 0");
  if (every < 1) throw krp::InputError("--every", "must be >= 1");
  mp.first = static_cast<std::size_t>(first);
  mp.every = static_cast<std::size_t>(every);
  const auto grid = krp::mapFromPosedScans(log.steps, log.logged_poses, mp);
  krp::writeRosMap(grid, args.get("out"));
  const std::size_t used = (log.steps.size() - mp.first + mp.every - 1) / mp.every;
  std::cout << "map from " << used << " of " << log.steps.size() << " scans (first " << mp.first << ", every " << mp.every
            << "): " << grid.getSizeX() << " x " << grid.getSizeY() << " cells at " << grid.getResolution() << " m, free "
            << krp::freeAreaM2(grid) << " m^2\nwritten: " << args.get("out") << "\n";
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-map-from-log", run, argc, argv); }
