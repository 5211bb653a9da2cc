// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/filter/look_alike_guard.h"
#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"
#include "mrpt_krp_plugin/relocalize/relocalizer.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/trial.h"

namespace krp {

/// What krp-bench-matcher measures: the correlative matcher's two kinds of search on simulated
/// first scans, each run with CorrelativeMatcherParams::stop_bound_early off and on, and (bounds
/// stopping early) over every heading and over the wall-heading windows
/// (MatchRequest::wall_heading_window_deg), and with the later solutions of a search started cold
/// and warm (CorrelativeMatcherParams::warm_start_later_solutions), and heading after heading and
/// across headings (CorrelativeMatcherParams::roots_across_headings), side by side on the same scan
/// (alternating which goes first), so that the ratios survive a noisy machine.
struct MatcherSpeedParams {
  int scans = 30;     ///< first scans of simulated trials, one per trial seed
  uint64_t seed = 1;  ///< trial i uses seed + i
  /// The matcher as the learned relocalizer's zone search, cross-check and look-alike guard use it.
  CorrelativeMatcherParams matcher;
  /// The look-alike search as the filter's guard runs it (its margin, node budget, see-through charge).
  LookAlikeGuardParams guard;
  TrialParams trial;  ///< where the scans come from (clutter, scanner noise)
  /// The windows of the wall-heading comparison [deg], for both searches (the guard's too): by
  /// default the relocalizer's, so that the report measures what the robot runs.
  double wall_heading_window_deg = RelocalizerParams{}.wall_heading_window_deg;
};

/// One kind of search over every scan, in a baseline setting and a variant.
struct MatcherSpeedRow {
  std::string search;          ///< "whole map" or "look-alike check"
  int scans = 0;
  double median_ms_baseline = 0.0;  ///< thread CPU per search in the baseline setting [ms]
  double median_ms_variant = 0.0;   ///< the same in the variant [ms]
  double median_ratio = 0.0;        ///< median over scans of baseline / variant time
  double total_ratio = 0.0;         ///< total baseline time / total variant time
  double median_nodes = 0.0;        ///< nodes scored per search in the variant
  double median_nodes_baseline = 0.0;
  double share_stopped_early = 0.0;  ///< of all the variant's nodes, those whose bound stopped early
  int differing = 0;                 ///< scans whose answer or node count differed
  int best_differing = 0;            ///< scans whose best answer differed
  int scores_differing = 0;          ///< scans whose solutions' scores differed, one by one
};

/// Both comparisons, row for row (whole map, then look-alike check).
struct MatcherSpeedRows {
  /// Every return read (baseline) against bounds that stop early: must answer alike (differing 0).
  std::vector<MatcherSpeedRow> stop_early;
  /// Every heading (baseline) against the wall-heading windows, bounds stopping early in both.
  /// Differing counts scans answered differently; the node counts differ by design.
  std::vector<MatcherSpeedRow> wall_headings;
  /// Each of the whole-map search's solutions from min_score (baseline) against the later ones
  /// warm-started (CorrelativeMatcherParams::warm_start_later_solutions), over every heading, then
  /// over the wall-heading windows. Scores must not differ; places only where two tie.
  std::vector<MatcherSpeedRow> warm_start;
  /// The depth-first search heading after heading (baseline) against the roots of every heading
  /// in one order (CorrelativeMatcherParams::roots_across_headings), over every heading, then over
  /// the wall-heading windows. Scores must not differ; places only where two tie.
  std::vector<MatcherSpeedRow> across_headings;
  /// Scans whose headings the windows narrowed (both wall directions clear), of all scans.
  int narrowed_scans = 0, scans = 0;
  /// Over the narrowed scans: the true heading's largest distance to the nearest window centre
  /// (beyond the window, the search cannot find the truth) [deg].
  double max_heading_error_deg = 0.0;
};

/// Runs the measurement on `map` (clutter is drawn into the simulation copy only). `progress`
/// is told after each scan. Throws InputError when the map has no pose a trial can start from.
MatcherSpeedRows measureMatcherSpeed(const mrpt::maps::COccupancyGridMap2D& map, const LidarProfile& lidar,
                                     const MatcherSpeedParams& params, const std::function<void()>& progress = {});

/// The stop-early rows as a Markdown table.
std::string matcherSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows);
/// The wall-heading rows as a Markdown table.
std::string wallHeadingSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows);
/// The warm-start rows as a Markdown table.
std::string warmStartSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows);
/// The roots-across-headings rows as a Markdown table.
std::string acrossHeadingsSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows);

}  // namespace krp
