// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/bench/trial_metrics.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_source.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"

namespace krp {

/// The relocalizer's answer for one scan of a log, relocalized on its own (no filter, no motion).
struct SingleScanRecord {
  std::size_t step = 0;
  bool localized = false;
  std::string reason;  ///< why not localized
  std::size_t hypotheses = 0;
  std::optional<mrpt::math::TPose2D> best;  ///< the best hypothesis, if any
  double confidence = 0.0;                  ///< of the best
  double fit_fraction = 0.0;                ///< of the best
  double time_ms = 0.0;                     ///< wall time of the relocalization
  double error_xy_m = -1.0;                 ///< best vs truth; -1 without truth or hypothesis
  double error_phi_deg = -1.0;
  bool best_right = false;  ///< the best is within the criteria's distance and heading of the truth
  /// The best came from the keypoint model's alignment, not from a correlative search (the
  /// learned relocalizer's zone search or cross-check, or the global matcher).
  bool best_from_keypoints = false;
};

/// Counts over a sweep. "right" and "wrong" need the truth.
struct SingleScanSummary {
  std::size_t scans = 0;
  std::size_t localized = 0;
  std::size_t localized_right = 0;
  std::size_t localized_wrong = 0;  ///< the confident-but-wrong answers that matter on a robot
  std::size_t best_right = 0;       ///< best hypothesis right, whatever the verdict
  /// Localized answers whose best came from the keypoint model: what the learned models carry
  /// themselves, against the correlative searches that check and back them up.
  std::size_t localized_from_keypoints = 0;
  bool has_truth = false;
  double median_error_xy_m = -1.0;     ///< over the localized answers; -1 without any
  double median_error_phi_deg = -1.0;  ///< over the localized answers
  double median_ms = 0.0;
  double p95_ms = 0.0;
};

/// Relocalizes every `stride`-th scan of `steps` on its own. `truth` (grid frame, one pose per
/// step) may be empty. `right` decides when a best hypothesis counts as right. Progress goes
/// to `progress` when it is not null.
std::vector<SingleScanRecord> sweepSingleScans(const HypothesisSource& source, const std::vector<RawlogStep>& steps,
                                               const std::vector<mrpt::math::TPose2D>& truth, std::size_t stride,
                                               const ConvergenceCriteria& right, std::ostream* progress);

SingleScanSummary summarizeSweep(const std::vector<SingleScanRecord>& records);

/// One row per record: step, verdict, best pose, confidence, fit, time, errors.
std::string sweepCsv(const std::vector<SingleScanRecord>& records);

/// The summary as lines of `key: value` for a _SUMMARY.txt.
std::string sweepSummaryText(const SingleScanSummary& s);

/// The map with the true path, and each scan's best hypothesis as a dot at its true position:
/// green localized and right, red localized but wrong, grey not localized. Written atomically.
void writeSweepPng(const mrpt::maps::COccupancyGridMap2D& map, const std::vector<SingleScanRecord>& records,
                   const std::vector<mrpt::math::TPose2D>& truth, const std::string& png_path);

}  // namespace krp
