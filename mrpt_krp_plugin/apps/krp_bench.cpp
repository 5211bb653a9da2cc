// SPDX-License-Identifier: BSD-3-Clause
// krp-bench: kidnapped-robot trials in simulated worlds, every method on the same trials.
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "cli_args.h"
#include "mrpt_krp_plugin/bench/bench_report.h"
#include "mrpt_krp_plugin/bench/kidnap_report.h"
#include "mrpt_krp_plugin/bench/bench_runner.h"
#include "mrpt_krp_plugin/bench/calibration_fit.h"
#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_source.h"

namespace fs = std::filesystem;
using krp::apps::CliArgs;
using krp::apps::kMaxParticles;
using krp::apps::kMaxZones;

/// More resamplings in a row than any run has updates: a uniform start that never shrinks.
constexpr long long kMaxShrinkWait = 100000;

static std::string methodList() {
  std::string s;
  for (const auto& m : krp::methodNames()) s += (s.empty() ? "" : ",") + m;
  return s;
}

static int run(int argc, char** argv) {
  CliArgs args("krp-bench",
               "Runs worlds x lidar profiles x methods x trials and writes trials.csv, updates.csv, summary.json, "
               "REPORT.md and plots. Methods: " + methodList(),
               {{"worlds", "A,B", "world names under --world-dir, or *.world.yaml paths", "office_two_zone"},
                {"world-dir", "DIR", "folder of the worlds", "sim_worlds"},
                {"lidars", "A,B", "lidar profiles (default: each world's default)", ""},
                {"methods", "A,B", "methods to compare", "uniform-mcl,amcl-kld"},
                {"trials", "N", "trials per world and lidar", "10"},
                {"only-trials", "I,J", "run only these trials (0-based, below --trials) with the seeds they have in "
                 "the full run: replays one trial of a report, given the run's --seed, --worlds and --lidars in the "
                 "same order (a trial's seed depends on its world's and lidar's place in those lists)", ""},
                {"steps", "N", "motion steps per trial after the first scan", "40"},
                {"kidnap-at", "STEP", "carry the robot elsewhere at this step (1..steps) and run every method with "
                 "kidnap detection; the report adds a kidnap table (0 = no kidnap)", "0"},
                {"kidnap-min-distance", "M", "--kidnap-at: the robot is carried at least this far", "5"},
                {"kidnap-detection", "", "run every method with the filter's kidnap detector on, kidnap or not: a "
                 "tracked pose that stops fitting the scans re-initializes the filter (the relocalizer again for "
                 "the seeded methods, a uniform spread for the others)", ""},
                {"seed", "N", "base seed (printed; every trial seed derives from it)", "1"},
                {"out", "DIR", "report folder", "out/bench"},
                {"uniform-particles", "N", "uniform-mcl: fixed particle count (0 = by density)", "0"},
                {"uniform-particles-per-m2", "D", "uniform-mcl: particles per m^2 of free space", "40"},
                {"kld-max", "N", "amcl-kld: max particles (amcl default)", "5000"},
                {"kld-min", "N", "amcl-kld: min particles (amcl default)", "100"},
                {"kld-high-max", "N", "amcl-kld-50k: max particles", "50000"},
                {"models-root", "DIR", "seeded methods: models of world W in DIR/W (krp-train-map's output)", "models"},
                {"models-for", "W=DIR,...", "seeded methods: world W reads its models from DIR instead (a changed "
                 "world run with the models of the map it changes)", ""},
                {"seeded-uniform-fraction", "F", "seeded: share of particles spread uniformly", "0.05"},
                {"seeded-max-particles", "N", "seeded: particle cap", "5000"},
                {"seeded-particles-per-hypothesis", "N", "seeded: particles around each hypothesis, before the "
                 "confidence split", std::to_string(krp::SeededInitParams{}.particles_per_hypothesis)},
                {"seeded-min-particles", "N", "seeded: fewest particles in all, uniform share included (and the "
                 "floor of a uniform start that shrinks)", std::to_string(krp::SeededInitParams{}.min_particles)},
                {"seeded-uniform-start-fixed", "", "seeded methods: a filter that started uniform (no hypothesis) "
                 "keeps its count to the end instead of shrinking by KLD sampling once converged "
                 "(SeededInitParams::fallback_shrinks unset; the seeded filter before it)", ""},
                {"seeded-uniform-start-shrinks-after", "N", "seeded methods: a uniform start shrinks only once its "
                 "set has been concentrated at N resamplings in a row (KldResamplingParams::concentrated_resamplings)",
                 std::to_string(krp::KldResamplingParams{}.concentrated_resamplings)},
                {"top-zones", "N", "seeded: zones whose keypoints are aligned", "2"},
                {"top-turns", "N", "seeded, wall-aligned models: submap turns the keypoint model runs on (the "
                 "classifier's surest)", std::to_string(krp::RelocalizerParams{}.top_turns)},
                {"keypoints-every-turn", "", "seeded: run the keypoint model on every one of the top turns, even "
                 "after one gave a credible answer (the relocalizer before it stopped there)", ""},
                {"search-zones", "N", "seeded: when the keypoints give no credible pose, the correlative matcher "
                 "searches this many of the classifier's most likely zones (0 = no zone search)", "1"},
                {"cross-check-places", "N", "seeded: other places the look-alike cross-check proposes per round "
                 "(each another branch-and-bound pass)", std::to_string(krp::CrossCheckParams{}.places)},
                {"guard-ambiguity-margin", "S", "methods with the look-alike guard: a place scoring within this of the "
                 "filter's mean (matcher score) makes the estimate ambiguous, so not confident (0 = only places that "
                 "fit at least as well)", krp::formatNumber(krp::LookAlikeGuardParams{}.ambiguity_margin)},
                {"guard-min-fit-fraction", "F", "methods with the look-alike guard: a converged estimate explaining fewer "
                 "than this share of the scan's returns is reported unsettled, so not confident (0 = off)",
                 krp::formatNumber(krp::LookAlikeGuardParams{}.min_fit_fraction)},
                {"guard-forget-rejected", "", "methods with the look-alike guard: a look-alike the scans decided against "
                 "is only left out of later searches, no longer watched (the guard before watching)", ""},
                {"no-see-through", "", "methods with the look-alike guard: weigh particles and look-alikes with the "
                 "likelihood field alone, without charging returns from beyond a mapped obstacle (the baselines never do)", ""},
                {"guard-search-ignores-see-through", "", "methods with the look-alike guard: the look-alike search "
                 "scores the returns' endpoints alone, without charging the places returns from beyond a mapped "
                 "obstacle (the filter and the rival test still charge them; the guard before this flag)", ""},
                {"matcher-heading-after-heading", "", "every correlative search (the relocalizer's, the guard's, "
                 "the global matcher's, the path check's) visits its coarsest nodes heading after heading instead "
                 "of across headings, highest bound first (the matcher before commit 61986f2: the same best scores, "
                 "but a place that ties exactly with another may be found instead of it)", ""},
                {"guard-max-search-nodes", "N", "methods with the look-alike guard: nodes one look-alike search charged "
                 "for see-through may score before it answers with the best place charged so far (0 = no limit)",
                 std::to_string(krp::LookAlikeGuardParams{}.max_search_nodes)},
                {"wall-heading-window", "DEG", "seeded methods: the relocalizer's zone search and cross-check try only "
                 "headings within DEG of the four that line the scan's walls up with the map's, when both have a "
                 "clear wall direction (0 = every heading)",
                 krp::formatNumber(krp::RelocalizerParams{}.wall_heading_window_deg)},
                {"guard-wall-heading-window", "DEG", "methods with the look-alike guard: the same for its search",
                 krp::formatNumber(krp::LookAlikeGuardParams{}.wall_heading_window_deg)},
                {"guard-nodes-per-update", "N", "methods with the look-alike guard: nodes of look-alike search one "
                 "filter update may score; a search charged for see-through that needs more pauses and goes on at the "
                 "next updates, the pose reading unverified meanwhile (0 = every search runs to its end at once)",
                 std::to_string(krp::LookAlikeGuardParams{}.max_nodes_per_update)},
                {"guard-unverified-is-settled", "", "methods with the look-alike guard: a converged filter whose "
                 "look-alike searches all ran out of --guard-max-search-nodes with nothing found reads as settled, "
                 "not widened (LookAlikeGuardParams::unverified_is_unsettled false; the guard before it)", ""},
                {"guard-refit-ignores-see-through", "", "methods with the look-alike guard: the rival test re-fits "
                 "each side to the likelihood alone and charges the see-through penalty where that puts it "
                 "(RivalTestParams::refit_charges_see_through false; the guard before it was the default)", ""},
                {"guard-history", "N", "methods with the look-alike guard: a new look-alike is also weighed on "
                 "the N scans before it, each side moved back along the odometry (LookAlikeGuardParams::"
                 "history_updates; 0 = the guard before it, the default)",
                 std::to_string(krp::LookAlikeGuardParams{}.history_updates)},
                {"guard-recheck-every", "N", "methods with the look-alike guard: while the filter stays converged, "
                 "the look-alike search runs again every N updates (LookAlikeGuardParams::recheck_every_updates; "
                 "0 = only when the filter converges afresh). Each search costs a whole-map correlative search: "
                 "on a large map with a long-range scanner, most of the seeded filter's time",
                 std::to_string(krp::LookAlikeGuardParams{}.recheck_every_updates)},
                {"guard-rival-refinements", "N", "methods with the look-alike guard: finer grids, each of half the "
                 "last one's steps, on which the rival test re-fits each side after its 5 cm / 1 deg grid "
                 "(RivalTestParams::finer_refinements; 0 = the test before that parameter)",
                 std::to_string(krp::RivalTestParams{}.finer_refinements)},
                {"min-localized-fit", "F", "relocalizing methods: the first scan's best hypothesis must explain at least "
                 "this share of its returns to be called localized (0 = off)",
                 krp::formatNumber(krp::HypothesisRankingParams{}.min_localized_fit_fraction)},
                {"calibration", "FILE", "relocalizing methods: a confidence calibration (--fit-calibration's output) "
                 "applied before the 'localized' threshold", ""},
                {"fit-calibration", "FILE", "fit a confidence calibration on this run's first-scan answers (one world, "
                 "one relocalizing method, no --calibration) and write it", ""},
                {"path-ambiguity", "", "check each trial (not kidnap trials) for places that explain its whole path as "
                 "well as the truth (those that fit its first scan nearly as well, and where each method ended "
                 "wrong), with the filter's sensor model: the report splits every method's outcome by "
                 "whether the scans tell the truth apart", ""},
                {"path-ambiguity-places", "N", "--path-ambiguity: first-scan places weighed per trial (the matcher's best; "
                 "0: only where the methods ended)", std::to_string(krp::PathAmbiguityParams{}.max_places)},
                {"tol-xy", "M", "convergence tolerance, position", "0.5"},
                {"tol-deg", "DEG", "convergence tolerance, heading", "10"},
                {"save-rawlogs", "", "also write each trial as an MRPT rawlog, a CARMEN log and its ground truth under OUT/rawlogs", ""}});
  if (!args.parse(argc, argv)) return 0;
  krp::BenchConfig cfg;
  for (const auto& w : args.list("worlds")) cfg.world_files.push_back(krp::apps::worldFilePath(w, args.get("world-dir")));
  cfg.lidars = args.list("lidars");
  cfg.methods = args.list("methods");
  cfg.trials = static_cast<int>(args.integer("trials"));
  for (const auto t : args.integerList("only-trials")) {
    if (t < 0 || t >= cfg.trials)
      throw krp::InputError("--only-trials", std::to_string(t) + " is not one of the run's trials 0.." + std::to_string(cfg.trials - 1));
    cfg.only_trials.push_back(static_cast<int>(t));
  }
  cfg.trial.steps = static_cast<int>(args.integer("steps"));
  if (cfg.trials < 1 || cfg.trial.steps < 0) throw krp::InputError("--trials/--steps", "must be >= 1 / >= 0");
  cfg.kidnap_at_step = static_cast<int>(args.integer("kidnap-at"));
  cfg.kidnap_min_distance_m = args.number("kidnap-min-distance");
  cfg.mcl.kidnap.enabled = args.flag("kidnap-detection");
  if (cfg.kidnap_at_step < 0 || cfg.kidnap_at_step > cfg.trial.steps)
    throw krp::InputError("--kidnap-at", "must be in 0.." + std::to_string(cfg.trial.steps) + " (the trial's steps)");
  cfg.seed = args.seed("seed");
  cfg.method_settings.uniform.particles = static_cast<size_t>(args.integerInRange("uniform-particles", 0, kMaxParticles));
  cfg.method_settings.uniform.particles_per_m2 = args.number("uniform-particles-per-m2");
  cfg.method_settings.amcl.max_particles = static_cast<size_t>(args.integerInRange("kld-max", 1, kMaxParticles));
  cfg.method_settings.amcl.min_particles = static_cast<size_t>(args.integerInRange("kld-min", 1, kMaxParticles));
  cfg.method_settings.amcl_high_max_particles = static_cast<size_t>(args.integerInRange("kld-high-max", 1, kMaxParticles));
  cfg.method_settings.models_root = args.get("models-root");
  for (const auto& pair : args.list("models-for")) {
    const auto eq = pair.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == pair.size())
      throw krp::InputError("--models-for", "expected WORLD=DIR, got '" + pair + "'");
    cfg.method_settings.models_by_world[pair.substr(0, eq)] = pair.substr(eq + 1);
  }
  cfg.method_settings.seeded.uniform_fraction = args.number("seeded-uniform-fraction");
  cfg.method_settings.seeded.max_particles = static_cast<size_t>(args.integer("seeded-max-particles"));
  for (const char* flag : {"seeded-max-particles", "seeded-particles-per-hypothesis", "seeded-min-particles"})
    if (args.integer(flag) < 1) throw krp::InputError(std::string("--") + flag, "must be 1 or more");
  cfg.method_settings.seeded.particles_per_hypothesis = static_cast<size_t>(args.integer("seeded-particles-per-hypothesis"));
  cfg.method_settings.seeded.min_particles = static_cast<size_t>(args.integer("seeded-min-particles"));
  const auto shrink_wait = static_cast<int>(args.integerInRange("seeded-uniform-start-shrinks-after", 1, kMaxShrinkWait));
  if (args.flag("seeded-uniform-start-fixed"))
    cfg.method_settings.seeded.fallback_shrinks.reset();
  else
    cfg.method_settings.seeded.fallback_shrinks->concentrated_resamplings = shrink_wait;
  cfg.method_settings.relocalizer.top_zones = static_cast<int>(args.integerInRange("top-zones", 0, kMaxZones));
  const auto top_turns = args.integer("top-turns");
  if (top_turns < 1 || top_turns > 4) throw krp::InputError("--top-turns", "must be 1 to 4");
  cfg.method_settings.relocalizer.top_turns = static_cast<int>(top_turns);
  cfg.method_settings.relocalizer.stop_turns_once_localized = !args.flag("keypoints-every-turn");
  const auto search_zones = args.integer("search-zones");
  if (search_zones < 0) throw krp::InputError("--search-zones", "must be 0 or more");
  cfg.method_settings.relocalizer.zone_search.zones = static_cast<int>(search_zones);
  const auto cross_check_places = args.integer("cross-check-places");
  if (cross_check_places < 1) throw krp::InputError("--cross-check-places", "must be 1 or more");
  cfg.method_settings.relocalizer.cross_check.places = static_cast<int>(cross_check_places);
  cfg.method_settings.guard.ambiguity_margin = args.number("guard-ambiguity-margin");
  if (!(cfg.method_settings.guard.ambiguity_margin >= 0.0 && cfg.method_settings.guard.ambiguity_margin <= 1.0))
    throw krp::InputError("--guard-ambiguity-margin", "must be in [0, 1]");
  cfg.method_settings.guard.min_fit_fraction = args.number("guard-min-fit-fraction");
  if (!(cfg.method_settings.guard.min_fit_fraction >= 0.0 && cfg.method_settings.guard.min_fit_fraction <= 1.0))
    throw krp::InputError("--guard-min-fit-fraction", "must be in [0, 1]");
  cfg.method_settings.guard.watch_rejected = !args.flag("guard-forget-rejected");
  cfg.mcl.see_through.enabled = !args.flag("no-see-through");
  cfg.path_ambiguity = args.flag("path-ambiguity");
  cfg.method_settings.guard.rival_test.refit_charges_see_through = !args.flag("guard-refit-ignores-see-through");
  cfg.method_settings.guard.history_updates = static_cast<int>(args.integer("guard-history"));
  if (cfg.method_settings.guard.history_updates < 0) throw krp::InputError("--guard-history", "must be 0 or more");
  cfg.method_settings.guard.rival_test.finer_refinements = static_cast<int>(args.integer("guard-rival-refinements"));
  if (cfg.method_settings.guard.rival_test.finer_refinements < 0)
    throw krp::InputError("--guard-rival-refinements", "must be 0 or more");
  cfg.path_ambiguity_params.max_places = static_cast<int>(args.integer("path-ambiguity-places"));
  if (cfg.path_ambiguity_params.max_places < 0) throw krp::InputError("--path-ambiguity-places", "must be >= 0");
  cfg.method_settings.guard.search_charges_see_through = !args.flag("guard-search-ignores-see-through");
  cfg.method_settings.guard.recheck_every_updates = static_cast<int>(
      args.integerInRange("guard-recheck-every", 0, krp::LookAlikeGuardParams::kMaxRecheckEveryUpdates));
  cfg.method_settings.guard.max_search_nodes =
      args.integerInRange("guard-max-search-nodes", 0, krp::LookAlikeGuardParams::kMaxSearchNodesLimit);
  cfg.method_settings.guard.max_nodes_per_update =
      args.integerInRange("guard-nodes-per-update", 0, krp::LookAlikeGuardParams::kMaxSearchNodesLimit);
  cfg.method_settings.guard.unverified_is_unsettled = !args.flag("guard-unverified-is-settled");
  krp::useMatcherRootsAcrossHeadings(!args.flag("matcher-heading-after-heading"), cfg.method_settings.relocalizer,
                                     cfg.method_settings.matcher);
  for (const char* flag : {"wall-heading-window", "guard-wall-heading-window"})
    if (!krp::MatchRequest::validWallHeadingWindow(args.number(flag)))
      throw krp::InputError(std::string("--") + flag, "must be " + krp::MatchRequest::wallHeadingWindowRange());
  cfg.method_settings.relocalizer.wall_heading_window_deg = args.number("wall-heading-window");
  cfg.method_settings.guard.wall_heading_window_deg = args.number("guard-wall-heading-window");
  krp::useMinLocalizedFitFraction(args.number("min-localized-fit"), cfg.method_settings.relocalizer,
                                  cfg.method_settings.matcher);
  const std::string calibration = args.get("calibration"), fit_calibration = args.get("fit-calibration");
  if (!calibration.empty()) {
    if (!fit_calibration.empty())
      throw krp::InputError("--fit-calibration", "fits raw confidences: leave out --calibration");
    krp::useConfidenceCalibration(krp::readConfidenceCalibration(calibration), cfg.method_settings.relocalizer,
                                  cfg.method_settings.matcher);
  }
  if (!fit_calibration.empty() && (cfg.world_files.size() != 1 || cfg.methods.size() != 1 ||
                                   !(krp::methodNeedsModels(cfg.methods[0]) || krp::methodNeedsMatcher(cfg.methods[0]))))
    throw krp::InputError("--fit-calibration", "needs one world and one relocalizing method (a calibration holds for one map)");
  cfg.criteria.max_error_xy_m = args.number("tol-xy");
  cfg.criteria.max_error_phi_deg = args.number("tol-deg");
  const std::string out = args.get("out");
  if (args.flag("save-rawlogs")) cfg.rawlog_dir = (fs::path(out) / "rawlogs").string();

  const auto records = krp::runBench(cfg, std::cerr);
  krp::writeBenchReport(records, cfg, args.commandLine(), out);
  if (!fit_calibration.empty()) {
    std::vector<krp::ConfidenceOutcome> answers;
    for (const auto& r : records)
      if (r.seed_best_confidence >= 0) answers.push_back(krp::firstScanAnswer(r, cfg.criteria.max_error_xy_m));
    krp::ConfidenceCalibration c;
    try {
      c = krp::fitConfidenceCalibration(answers);
    } catch (const std::invalid_argument& e) {
      throw krp::InputError("--fit-calibration", e.what());
    }
    c.fitted_by = args.commandLine();
    krp::writeConfidenceCalibration(c, fit_calibration);
    std::cout << "calibration: slope " << c.slope << ", offset " << c.offset << " from " << c.answers << " answers -> "
              << fit_calibration << "\n";
  }
  std::cout << "\n" << krp::summaryTable(krp::summarize(records, cfg.criteria.max_error_xy_m)) << "\n"
            << krp::kidnapSection(krp::summarizeKidnaps(records), cfg.kidnap_at_step) << "Report: " << (fs::path(out) / "REPORT.md").string()
            << " (trials.csv, updates.csv, summary.json, plots beside it)\n";
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-bench", run, argc, argv); }
