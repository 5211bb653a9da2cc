// SPDX-License-Identifier: BSD-3-Clause
// krp-bench-matcher: the correlative matcher's searches with bounds that stop early against
// bounds that read every return, side by side on the same simulated scans.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli_args.h"
#include "mrpt_krp_plugin/bench/matcher_speed.h"
#include "mrpt_krp_plugin/bench/method_registry.h"
#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/progress_bar.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/sim/lidar_profile_file.h"
#include "mrpt_krp_plugin/sim/world.h"

using krp::apps::CliArgs;

static int run(int argc, char** argv) {
  const krp::MatcherSpeedParams defaults;
  CliArgs args("krp-bench-matcher",
               "Times the correlative matcher's two searches on the first scans of simulated trials: the whole-map "
               "search (global matcher, zone search) and the look-alike check (the filter's guard, the relocalizer's "
               "cross-check), each with node bounds that stop reading returns once the node cannot win and with "
               "bounds that read every return, side by side on the same scan. Both must give the same answers and "
               "node counts (exit code 1 otherwise). Then, bounds stopping early, the same searches over every heading "
               "and over the headings that line the scan's walls up with the map's. Writes REPORT.md.",
               {{"world", "NAME", "world name under --world-dir, or a *.world.yaml path (its map, lidar, clutter)",
                 "warehouse"},
                {"world-dir", "DIR", "folder of the worlds", "sim_worlds"},
                {"map", "FILE", "a map instead of a world (.yaml, .gridmap[.gz], .bt/.ot; clutter: the defaults)", ""},
                {"lidar", "NAME|FILE", "lidar profile, built-in name or profile file (default: the world's default, "
                 "or omni_12m with --map)", ""},
                {"scans", "N", "scans (one simulated trial each)", std::to_string(defaults.scans)},
                {"seed", "N", "trial i uses seed + i", std::to_string(defaults.seed)},
                {"wall-heading-window", "DEG", "the wall-heading comparison's windows (above 0, at most 45)",
                 krp::formatNumber(defaults.wall_heading_window_deg)},
                {"out", "DIR", "report folder", "out/bench_matcher"}});
  if (!args.parse(argc, argv)) return 0;
  krp::MatcherSpeedParams params;
  params.scans = static_cast<int>(args.integer("scans"));
  if (params.scans < 1) throw krp::InputError("--scans", "must be at least 1");
  params.seed = args.seed("seed");
  params.wall_heading_window_deg = args.number("wall-heading-window");
  const krp::MethodSettings settings;  // the matcher and guard as every method runs them
  params.matcher = settings.relocalizer.matcher;
  params.guard = settings.guard;
  std::string map_path, lidar_name;
  krp::LidarProfile lidar;
  if (args.has("map")) {
    map_path = args.get("map");
    lidar_name = args.has("lidar") ? args.get("lidar") : "omni_12m";
    lidar = krp::lidarProfile(lidar_name);
  } else {
    const auto world = krp::readWorld(krp::apps::worldFilePath(args.get("world"), args.get("world-dir")));
    map_path = world.map_path;
    lidar_name = args.has("lidar") ? args.get("lidar") : world.default_lidar_profile;
    lidar = world.lidarOrProfileFile(lidar_name);
    params.trial.clutter = world.clutter;
  }
  const auto map = krp::loadOccupancyMap(map_path);
  krp::ProgressBar bar("scans", static_cast<std::size_t>(params.scans), std::cerr);
  const auto rows = krp::measureMatcherSpeed(*map.grid, lidar, params, [&] { bar.advance(); });
  bar.finish();

  const std::string out = args.get("out");
  std::filesystem::create_directories(out);
  std::ostringstream md;
  md << "# Correlative matcher: bounds that stop early, wall headings, warm starts, roots across headings\n\nCommand:\n\n```\n" << args.commandLine() << "\n```\n\n"
     << "Map `" << map_path << "` (" << krp::freeAreaM2(*map.grid) << " m^2 free), lidar " << lidar_name << " ("
     << lidar.fov_rad * 180.0 / M_PI << " deg, " << lidar.beams << " beams, " << lidar.max_range_m << " m). Each scan is the first "
     << "of a simulated trial (clutter drawn into the simulation only) and is searched by two matchers built alike "
     << "but for `stop_bound_early`, taking turns at going first; times are the thread's CPU per search. *Whole "
     << "map*: `CorrelativeMatcher::match` with its defaults (depth-first, two solutions), as the global matcher and "
     << "the zone search run it. *Look-alike check*: `LookAlikeGuard::lookAlike` at the true pose, as the filter's "
     << "guard and the relocalizer's cross-check run it (best-first, a bar just under the pose's own score, "
     << "see-through returns charged). *Scans answered differently* counts scans whose answers, scores or node "
     << "counts differ between the two: it must be 0.\n\n"
     << krp::matcherSpeedMarkdown(rows.stop_early) << "\n## Headings from the walls\n\n"
     << "The same scans, bounds stopping early in both: every heading of the turn against only those within "
     << krp::formatNumber(params.wall_heading_window_deg) << " deg of the four that line the scan's walls up with the "
     << "map's (`MatchRequest::wall_heading_window_deg`; every heading still when the map's or the scan's wall "
     << "direction holds less than " << krp::formatNumber(params.matcher.min_wall_support) << " of its wall length). "
     << "Taking turns at going first. An answer that differs has another place, heading or score (the "
     << "whole-map search gives two solutions, the look-alike check one): a tie broken in another order, or a place "
     << "at a heading outside the windows. The windows narrowed the headings of "
     << rows.narrowed_scans << " of " << rows.scans << " scans; on those, the true heading lay at most "
     << krp::formatNumber(rows.max_heading_error_deg) << " deg from the nearest window's centre.\n\n"
     << krp::wallHeadingSpeedMarkdown(rows.wall_headings) << "\n## Later solutions started warm\n\n"
     << "The same scans, bounds stopping early in both: the whole-map search's second solution searched from "
     << "`min_score`, against searched from the best candidate the first solution's search passed on its way that "
     << "may still be a solution (`CorrelativeMatcherParams::warm_start_later_solutions`), so that it prunes from "
     << "that score on; over every heading (the global matcher), then over the wall-heading windows (the zone "
     << "search's setting). Taking turns at going first. *Scores differ* counts scans whose solutions score "
     << "differently, one by one: it must be 0. *Places differ* counts those whose solutions stand elsewhere: only "
     << "where two places score exactly alike, a tie broken in another order.\n\n"
     << krp::warmStartSpeedMarkdown(rows.warm_start) << "\n## Roots across headings\n\n"
     << "The same scans, bounds stopping early and later solutions warm-started in both: the whole-map search "
     << "heading after heading, against the coarsest nodes of every heading visited in one order, highest bound "
     << "first (`CorrelativeMatcherParams::roots_across_headings`), so that the best place tends to be reached "
     << "sooner and prunes the other headings; over every heading, then over the wall-heading windows. Taking turns "
     << "at going first. *Scores differ* counts scans whose solutions score differently, one by one: it must be 0. "
     << "*Places differ* counts those whose solutions stand elsewhere: only where two places score exactly alike, a "
     << "tie broken in another order.\n\n"
     << krp::acrossHeadingsSpeedMarkdown(rows.across_headings);
  krp::writeFileAtomically(out + "/REPORT.md", md.str());
  std::cout << md.str() << "\nReport: " << out << "/REPORT.md\n";
  for (const auto& r : rows.stop_early)
    if (r.differing > 0) {
      std::cerr << "krp-bench-matcher: the " << r.search << " search answered " << r.differing
                << " scan(s) differently with bounds that stop early\n";
      return 1;
    }
  for (const auto& r : rows.warm_start)
    if (r.scores_differing > 0) {
      std::cerr << "krp-bench-matcher: the " << r.search << " search scored " << r.scores_differing
                << " scan(s) differently with its later solutions warm-started\n";
      return 1;
    }
  for (const auto& r : rows.across_headings)
    if (r.scores_differing > 0) {
      std::cerr << "krp-bench-matcher: the " << r.search << " search scored " << r.scores_differing
                << " scan(s) differently with its roots across headings\n";
      return 1;
    }
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-bench-matcher", run, argc, argv); }
