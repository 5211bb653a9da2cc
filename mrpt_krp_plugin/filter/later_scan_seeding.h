// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/filter_spread.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_ranking.h"

namespace krp {

/// A filter seeded from its first scan that is still unsure of its pose relocalizes later scans
/// and gives each of their hypotheses it lacks a share of its particles. When every hypothesis of
/// the first scan is wrong, only the uniform share's few particles can land near the truth (about
/// 40 of the warehouse's 790 over 2,000 m^2 of floor), so the scans that would tell the truth
/// apart find nothing there to favour; a later scan's relocalization often names it.
struct LaterScanSeedingParams {
  bool enabled = false;  ///< off: only the first scan seeds the filter (krp-bench's `seeded-later-scans` turns it on)
  /// Later scans relocalized per initialization at most: each costs one relocalization.
  int max_scans = 5;
  /// The filter is unsure while its particles' spread at the last update is not below these, or
  /// while the look-alike guard found the scan unexplained at their mean (MclEstimate::
  /// scan_unexplained). Particles gathered on a place that explains the scan are left to the
  /// guard, whose rival test weighs the look-alikes: relocalizing there too put particles on a
  /// look-alike of the truth and lost it (warehouse trial 52, docs/results.md).
  ConcentrationThresholds unsure;
  /// Each hypothesis that lacks particles gets this share of the set (0, 1 / max_hypotheses].
  double share_per_hypothesis = 0.1;
  int max_hypotheses = 3;  ///< of a scan's hypotheses, the best this many may get particles
  /// A hypothesis that already holds half its share within this distance and heading keeps the
  /// particles it has: the filter already weighs that place.
  double covered_xy_m = 1.0;
  double covered_phi_deg = 15.0;
  /// The moved particles' spread around the hypothesis: the seeded prior's narrowest cloud
  /// (SeededInitParams::min_std_xy_m and min_std_yaw_deg), which the motion noise keeps alive.
  double spread_xy_m = 0.15;
  double spread_phi_deg = 3.0;
};

/// InputError naming the first parameter out of its range.
void validate(const LaterScanSeedingParams& params);

/// Gives each of `ranking`'s best hypotheses (poses at the time of its scan) that holds too few
/// particles its share, drawn around it and moved back by `motion`, the odometry of the update
/// that is about to weigh that scan, so that the update's prediction carries them to the
/// hypothesis. The moved particles are every k-th of the set (k = 1 / share), each hypothesis
/// its own k-th, so every place the filter holds loses the same proportion. When any moved,
/// every weight is reset: the scan and those that follow decide between the places. Returns how
/// many hypotheses got particles.
int seedFromLaterScan(mrpt::slam::CMonteCarloLocalization2D& pf, const Ranking& ranking,
                      const mrpt::poses::CPose2D& motion, const LaterScanSeedingParams& params, Rng& rng);

}  // namespace krp
