// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/filter/look_alike_guard.h"
#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/trial.h"

namespace krp {

/// What krp-bench-matcher measures: the correlative matcher's two kinds of search on simulated
/// first scans, each run with CorrelativeMatcherParams::stop_bound_early off and on, side by side
/// on the same scan (alternating which goes first), so that the ratio survives a noisy machine.
struct MatcherSpeedParams {
  int scans = 30;     ///< first scans of simulated trials, one per trial seed
  uint64_t seed = 1;  ///< trial i uses seed + i
  /// The matcher as the learned relocalizer's zone search, cross-check and look-alike guard use it.
  CorrelativeMatcherParams matcher;
  /// The look-alike search as the filter's guard runs it (its margin, node budget, see-through charge).
  LookAlikeGuardParams guard;
  TrialParams trial;  ///< where the scans come from (clutter, scanner noise)
};

/// One kind of search over every scan.
struct MatcherSpeedRow {
  std::string search;          ///< "whole map" or "look-alike check"
  int scans = 0;
  double median_ms_reading_all = 0.0;  ///< thread CPU per search, every return read [ms]
  double median_ms_stopping = 0.0;     ///< the same with bounds that stop early [ms]
  double median_ratio = 0.0;           ///< median over scans of reading-all / stopping time
  double total_ratio = 0.0;            ///< total reading-all time / total stopping time
  double median_nodes = 0.0;           ///< nodes scored per search (the same both ways)
  double share_stopped_early = 0.0;    ///< of all nodes scored, those whose bound stopped early
  int differing = 0;                   ///< scans whose answer or node count differed (should be 0)
};

/// Runs the measurement on `map` (clutter is drawn into the simulation copy only). `progress`
/// is told after each scan. Throws InputError when the map has no pose a trial can start from.
std::vector<MatcherSpeedRow> measureMatcherSpeed(const mrpt::maps::COccupancyGridMap2D& map, const LidarProfile& lidar,
                                                 const MatcherSpeedParams& params,
                                                 const std::function<void()>& progress = {});

/// The rows as a Markdown table.
std::string matcherSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows);

}  // namespace krp
