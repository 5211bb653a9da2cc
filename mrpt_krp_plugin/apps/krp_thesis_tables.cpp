// SPDX-License-Identifier: BSD-3-Clause
// krp-thesis-tables: the thesis's comparisons with classical methods (its Tables 4.4 and 4.5) on
// one world: SIFT and ORB zoning against the CNN, ICP from the zone's centre against the
// keypoint alignment.
#include <filesystem>
#include <iostream>

#include "cli_args.h"
#include "mrpt_krp_plugin/bench/thesis_comparison.h"
#include "mrpt_krp_plugin/bench/thesis_comparison_report.h"
#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/sim/world.h"

using krp::apps::CliArgs;

static int run(int argc, char** argv) {
  const krp::ThesisComparisonParams defaults;
  CliArgs args("krp-thesis-tables",
               "The thesis's comparisons with classical methods on one world: zone classification by SIFT and ORB "
               "matching against the shipped CNN (Table 4.4), and the pose from ICP started at the zone's centre "
               "against the keypoint alignment (Table 4.5). Writes REPORT.md and samples.csv.",
               {{"world", "NAME", "world name under --world-dir, or a *.world.yaml path", "office_two_zone"},
                {"world-dir", "DIR", "folder of the worlds", "sim_worlds"},
                {"lidar", "NAME", "lidar profile (default: the world's default)", ""},
                {"models", "DIR", "the models (krp-train-map's output; default: models/<world>)", ""},
                {"references", "N", "reference submaps per zone for SIFT/ORB", std::to_string(defaults.references_per_zone)},
                {"tests", "N", "held-out submaps per zone", std::to_string(defaults.tests_per_zone)},
                {"seed", "N", "base seed", std::to_string(defaults.seed)},
                {"no-clutter", "", "scenes as mapped, without unmapped objects", ""},
                {"out", "DIR", "report folder", "out/thesis_tables"}});
  if (!args.parse(argc, argv)) return 0;
  const auto world = krp::readWorld(krp::apps::worldFilePath(args.get("world"), args.get("world-dir")));
  const std::string lidar = args.has("lidar") ? args.get("lidar") : world.default_lidar_profile;
  const std::string models = args.has("models") ? args.get("models") : "models/" + world.name;
  krp::ThesisComparisonParams params;
  params.references_per_zone = static_cast<int>(args.integer("references"));
  params.tests_per_zone = static_cast<int>(args.integer("tests"));
  params.seed = args.seed("seed");
  params.clutter = !args.flag("no-clutter");
  const auto comparison = krp::runThesisComparison(world, lidar, models, params, std::cerr);
  const std::string out = args.get("out");
  std::filesystem::create_directories(out);
  const auto report = krp::thesisComparisonMarkdown(comparison, args.commandLine());
  krp::writeFileAtomically(out + "/REPORT.md", report);
  krp::writeFileAtomically(out + "/samples.csv", krp::thesisComparisonCsv(comparison));
  std::cout << report << "\nReport: " << out << "/REPORT.md\n";
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-thesis-tables", run, argc, argv); }
