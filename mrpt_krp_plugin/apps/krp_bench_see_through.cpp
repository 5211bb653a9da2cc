// SPDX-License-Identifier: BSD-3-Clause
// krp-bench-see-through: the filter's see-through charge of a particle cloud with the rays
// marched side by side against one at a time, on the same simulated scans and particles.
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli_args.h"
#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/bench/see_through_speed.h"
#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/progress_bar.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/sim/world.h"

using krp::apps::CliArgs;

static int run(int argc, char** argv) {
  const krp::SeeThroughSpeedParams defaults;
  CliArgs args("krp-bench-see-through",
               "Times the see-through charge a filter update puts on each particle (the share of a scan's beams whose "
               "return lies beyond a mapped wall), over a cloud of particles around the true pose of simulated first "
               "scans: the rays marched side by side (what the filter and the look-alike guard run) against one at a "
               "time, on the same scans and particles, taking turns at going first. Both must count alike, particle "
               "by particle (exit code 1 otherwise). Writes REPORT.md.",
               {{"world", "NAME", "world name under --world-dir, or a *.world.yaml path (its map, lidar, clutter)",
                 "office_two_zone"},
                {"world-dir", "DIR", "folder of the worlds", "sim_worlds"},
                {"lidar", "NAME|FILE", "lidar profile, built-in name or profile file (default: the world's)", ""},
                {"scans", "N", "scans (one simulated trial each)", std::to_string(defaults.scans)},
                {"seed", "N", "trial i uses seed + i", std::to_string(defaults.seed)},
                {"particles", "N", "particles per scan, drawn around the true pose", std::to_string(defaults.particles)},
                {"spread-m", "M", "their position std", krp::formatNumber(defaults.spread_m)},
                {"spread-deg", "DEG", "their heading std", krp::formatNumber(defaults.spread_deg)},
                {"repeats", "N", "each cloud charged this many times each way, the fastest kept",
                 std::to_string(defaults.repeats)},
                {"out", "DIR", "report folder", "out/bench_see_through"}});
  if (!args.parse(argc, argv)) return 0;
  krp::SeeThroughSpeedParams params;
  params.scans = static_cast<int>(args.integer("scans"));
  params.particles = static_cast<int>(args.integer("particles"));
  params.repeats = static_cast<int>(args.integer("repeats"));
  if (params.scans < 1) throw krp::InputError("--scans", "must be at least 1");
  if (params.particles < 1) throw krp::InputError("--particles", "must be at least 1");
  if (params.repeats < 1) throw krp::InputError("--repeats", "must be at least 1");
  params.seed = args.seed("seed");
  params.spread_m = args.number("spread-m");
  params.spread_deg = args.number("spread-deg");
  if (!(params.spread_m >= 0)) throw krp::InputError("--spread-m", "must be >= 0");
  if (!(params.spread_deg >= 0)) throw krp::InputError("--spread-deg", "must be >= 0");
  const auto world = krp::readWorld(krp::apps::worldFilePath(args.get("world"), args.get("world-dir")));
  const std::string lidar_name = args.has("lidar") ? args.get("lidar") : world.default_lidar_profile;
  const auto lidar = world.lidarOrProfileFile(lidar_name);
  params.trial.clutter = world.clutter;
  const auto map = krp::loadOccupancyMap(world.map_path);
  krp::ProgressBar bar("scans", static_cast<std::size_t>(params.scans), std::cerr);
  const auto r = krp::measureSeeThroughSpeed(*map.grid, lidar, params, [&] { bar.advance(); });
  bar.finish();

  const std::string out = args.get("out");
  std::filesystem::create_directories(out);
  std::ostringstream md;
  md << "# The see-through charge: rays side by side against one at a time\n\nCommand:\n\n```\n" << args.commandLine()
     << "\n```\n\nMap `" << world.map_path << "`, lidar " << lidar_name << " (" << lidar.beams << " beams, "
     << krp::formatNumber(lidar.max_range_m) << " m). Each scan is the first of a simulated trial; " << params.particles
     << " particles are drawn around its true pose (std " << krp::formatNumber(params.spread_m) << " m, "
     << krp::formatNumber(params.spread_deg) << " deg) and each is charged the scan's see-through beams (every "
     << params.filter.sensor.decimation << "th beam with a return, " << r.checked_beams << " on the last scan), as a "
     << "filter update does: `SeeThroughPenalty::Scan::count`, which marches several rays side by side, against "
     << "`countOneRayAtATime`, each ray to its end before the next. Times are the thread's CPU for the whole cloud, "
     << "the fastest of " << params.repeats << " repeats, the two taking turns at going first. *Particles counted "
     << "differently* must be 0.\n\n"
     << "| scans | particles charged per way | beams seen through per particle, mean | one at a time, median ms | "
        "side by side, median ms | ratio, median over scans | ratio, total | particles counted differently |\n"
     << "|---|---|---|---|---|---|---|---|\n"
     << "| " << r.scans << " | " << r.particle_charges << " | " << krp::formatNumber(r.mean_seen_through) << " | "
     << krp::formatNumber(r.median_ms_one_at_a_time) << " | " << krp::formatNumber(r.median_ms_side_by_side) << " | "
     << krp::formatNumber(r.median_ratio) << "x | " << krp::formatNumber(r.total_ratio) << "x | " << r.differing << " |\n";
  krp::writeFileAtomically(out + "/REPORT.md", md.str());
  std::cout << md.str() << "\nReport: " << out << "/REPORT.md\n";
  if (r.differing > 0) {
    std::cerr << "krp-bench-see-through: " << r.differing << " particle(s) counted differently side by side\n";
    return 1;
  }
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-bench-see-through", run, argc, argv); }
