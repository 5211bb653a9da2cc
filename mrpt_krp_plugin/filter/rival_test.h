// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>

#include "mrpt_krp_plugin/filter/see_through.h"

namespace krp {

/// A look-alike place that fits one scan nearly as well as the tracked pose is not yet a reason
/// to doubt it: the scans that follow usually tell the two apart, and the filter's own sensor
/// model says by how much. The test adds up, scan after scan, the log-likelihood ratio of the
/// tracked pose against the rival (a sequential probability ratio test) and decides when either
/// side leads by a set amount.
struct RivalTestParams {
  /// Accumulated log-likelihood ratio that decides [nats of the filter's sensor model]. The
  /// model treats every used beam as independent, which overstates the evidence of one scan, so
  /// the bar is well above the textbook log(100) ~ 4.6.
  double decisive_log_ratio = 20.0;
  /// Both poses are re-fitted to each scan by trying these offsets on a 3 x 3 x 3 grid around
  /// them, so that neither side loses for being a few centimetres off (the rival comes from the
  /// matcher's grid and is moved by odometry alone) [m], [deg].
  double refine_step_m = 0.05;
  double refine_step_deg = 1.0;
  /// ... then on as many more 3 x 3 x 3 grids, each of half the last one's steps
  /// (refinedPoseOnGrids: a side held half a step off its best loses nats a scan to noise, and in
  /// a place copied exactly elsewhere, the corridor's mirror image or the warehouse's aisles,
  /// that noise decides the test). 0: the first grid only (the test before this parameter).
  int finer_refinements = 3;
  /// With a see-through penalty, re-fit each side to the likelihood less that penalty, not to
  /// the likelihood alone. A beam that grazes a rack's corner sees through or not as the pose
  /// moves a few centimetres, and one such beam costs as much as the likelihood field tells two
  /// look-alike aisles apart by in a whole scan: fitted to the likelihood alone, whichever side
  /// happens to graze loses on noise (the warehouse's trial 8 was decided for the wrong aisle
  /// that way). false: the penalty is charged where the likelihood alone puts each side (the
  /// guard's rival test until this became the default; krp-bench --guard-refit-ignores-see-through).
  bool refit_charges_see_through = true;
};

/// Throws std::invalid_argument for a decisive ratio that is not positive, a negative
/// refinement step or refinement count: what RivalTest refuses, for owners that check their settings up front.
void validateRivalTestParams(const RivalTestParams& params);

class RivalTest {
 public:
  enum class Verdict { undecided, tracked_wins, rival_wins };

  /// Throws as validateRivalTestParams does.
  explicit RivalTest(const mrpt::math::TPose2D& rival, RivalTestParams params = {});

  /// Moves the rival by the robot's odometry increment since the last scan.
  void move(const mrpt::poses::CPose2D& increment);

  /// Adds one scan's evidence: the log-likelihood at the (re-fitted) tracked pose minus that at
  /// the (re-fitted) rival, with `map`'s likelihood options, and with the filter's see-through
  /// penalty for this scan when it has one (the same model the particles are weighed with).
  Verdict update(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
                 const mrpt::math::TPose2D& tracked, const SeeThroughPenalty::Scan* see_through = nullptr);

  /// Holds the evidence for the tracked pose at `cap` at most: a rival decided against keeps
  /// being weighed (the guard watches it), and fresh evidence the other way needs to undo only
  /// this much, not everything the tracked pose ever gathered.
  void holdLeadAt(double cap) { log_ratio_ = std::min(log_ratio_, cap); }

  const mrpt::math::TPose2D& rival() const { return rival_; }
  double logRatio() const { return log_ratio_; }  ///< > 0 favours the tracked pose [nats]

 private:
  /// The best log-likelihood over the refinement grid around `pose`, less `see_through`'s
  /// penalty where given (charged at the best pose, or over the grid with
  /// refit_charges_see_through); `pose` is moved to the best.
  double refinedLogLikelihood(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
                              mrpt::math::TPose2D& pose, const SeeThroughPenalty::Scan* see_through) const;

  mrpt::math::TPose2D rival_;
  RivalTestParams params_;
  double log_ratio_ = 0.0;
};

}  // namespace krp
