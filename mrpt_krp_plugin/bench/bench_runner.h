// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/bench/method_registry.h"
#include "mrpt_krp_plugin/bench/path_ambiguity.h"
#include "mrpt_krp_plugin/bench/trial_metrics.h"
#include "mrpt_krp_plugin/relocalize/relocalization_times.h"
#include "mrpt_krp_plugin/sim/trial.h"

namespace krp {

struct BenchConfig {
  std::vector<std::string> world_files;  ///< `*.world.yaml`
  std::vector<std::string> lidars;       ///< profile names; empty = each world's default
  std::vector<std::string> methods = {"uniform-mcl", "amcl-kld"};
  int trials = 10;
  /// When not empty, only these trials (indices 0 .. trials - 1) are run, with the seeds they
  /// have in the full run: one trial of a report replayed alone, to study it.
  std::vector<int> only_trials;
  uint64_t seed = 1;
  TrialParams trial;
  MethodSettings method_settings;
  MclParams mcl;
  ConvergenceCriteria criteria;
  std::string rawlog_dir;  ///< when set, each trial is also written as a rawlog, a CARMEN log + ground truth
  /// Kidnap mid-run: at this step (1 .. trial.steps) the robot is carried to the start of a
  /// second trial, and every method runs with the filter's kidnap detector on. 0 = no kidnap.
  int kidnap_at_step = 0;
  /// The robot is carried at least this far (a second trial starting closer is redrawn). [m]
  double kidnap_min_distance_m = 5.0;
  int kidnap_max_draws = 50;  ///< second trials drawn before the map is declared too small
  /// Weigh, once per trial, whether another place explains its whole path as well as the truth
  /// (PathAmbiguityCheck, with the filter's sensor model and see-through setting): the limit any
  /// method faces. Not done for kidnap trials.
  bool path_ambiguity = false;
  PathAmbiguityParams path_ambiguity_params;
};

/// One method on one trial.
struct TrialRecord {
  std::string world, lidar, method;
  int trial = 0;
  uint64_t trial_seed = 0, filter_seed = 0;
  double free_area_m2 = 0.0;
  /// Seeded methods: the model folder and its two models' sha256 (checked against the files on
  /// load), so a report names the models it measured; empty for the others.
  std::string models;
  TrialOutcome outcome;
  std::vector<UpdateRecord> updates;
  /// Methods that relocalize from the first scan (seeded, global-matcher): what the relocalizer answered.
  int seed_hypotheses = -1;        ///< -1 for methods without a relocalizer
  bool seed_localized = false;     ///< it called itself localized
  double seed_best_error_xy_m = -1.0;  ///< its best hypothesis's distance to the truth [m]; -1 without one
  double seed_best_confidence = -1.0;  ///< the confidence it gave its best hypothesis; -1 without one
  bool seed_best_from_matcher = false;  ///< its best came from a correlative search (seeded: the zone search)
  double seed_best_fit_fraction = -1.0;  ///< share of that scan's returns its best explains (ScanFit); -1 without one
  double seed_cpu_s = -1.0;        ///< thread CPU from that scan to the drawn prior [s]; -1 without one
  /// Where that relocalization's time went, stage by stage (the learned relocalizer only).
  std::optional<RelocalizationTimes> seed_stage_times;
  int kidnap_step = -1;            ///< the update the robot was carried before; -1 without a kidnap
  KidnapOutcome kidnap;            ///< valid when kidnap_step >= 0
  PathAmbiguity path;              ///< the trial's, the same for every method (BenchConfig::path_ambiguity)
};

/// Runs worlds x lidars x methods x trials. Each trial is simulated once and replayed for
/// every method with the same filter seed, so methods are compared on identical input.
std::vector<TrialRecord> runBench(const BenchConfig& config, std::ostream& log);

}  // namespace krp
