// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/bench/bench_runner.h"
#include "mrpt_krp_plugin/bench/reliability.h"

namespace krp {

/// Medians and rates of one method on one world and lidar.
struct MethodSummary {
  std::string world, lidar, method;
  int trials = 0;
  double success_rate = 0.0;                 ///< converged / trials
  double confident_wrong_rate = 0.0;         ///< confident but wrong / trials
  double confident_right_rate = 0.0;         ///< confident and right at the end / trials: what hedging costs
  double median_updates = 0.0;               ///< over converged trials
  double median_distance_m = 0.0;            ///< over converged trials
  double median_cpu_s = 0.0;                 ///< CPU to convergence, over converged trials
  double median_initial_particles = 0.0;
  double median_mean_particles = 0.0;
  double median_particle_updates = 0.0;      ///< over converged trials
  double median_final_error_m = 0.0;         ///< over all trials
  double median_final_error_converged_m = 0.0;  ///< over converged trials
  double median_final_error_phi_deg = 0.0;   ///< over converged trials
  /// Methods that relocalize from the first scan (seeded, global-matcher): its answer; negative for others.
  double seed_localized_rate = -1.0;    ///< it called itself localized / trials
  double seed_best_right_rate = -1.0;   ///< its best hypothesis was within max_error_xy_m of the truth / trials
  double seed_localized_wrong_rate = -1.0;  ///< it called itself localized and its best was not right / trials
  double seed_best_from_matcher_rate = -1.0;  ///< its best came from a correlative search / trials
  double median_seed_cpu_s = -1.0;  ///< thread CPU from the scan to the drawn prior, median over trials [s]
  double p90_seed_cpu_s = -1.0;     ///< its 90th percentile [s]
};

std::vector<MethodSummary> summarize(const std::vector<TrialRecord>& records, double right_within_m = 0.5);

/// The relocalizer's best first-scan hypothesis was right: within `right_within_m` of the truth.
bool seedBestRight(const TrialRecord& r, double right_within_m);

/// That hypothesis's confidence and whether it was right, for reliability tables and calibration
/// fits; meaningful when the relocalizer gave one (seed_best_confidence >= 0).
ConfidenceOutcome firstScanAnswer(const TrialRecord& r, double right_within_m);

/// The first-scan relocalization of the methods that have one (seeded, global-matcher), before
/// the filter runs, as a Markdown table with its legend; empty when no method has one.
std::string relocalizerTable(const std::vector<MethodSummary>& summaries, double right_within_m);

/// The Markdown table of summaries, with ratios against `reference_method` where present.
std::string summaryTable(const std::vector<MethodSummary>& summaries, const std::string& reference_method = "uniform-mcl");

/// Writes `trials.csv`, `updates.csv`, `summary.json`, `REPORT.md` and the PNG plots into
/// `out_dir`. Every file is written atomically.
void writeBenchReport(const std::vector<TrialRecord>& records, const BenchConfig& config, const std::string& command_line,
                      const std::string& out_dir);

}  // namespace krp
