// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

#include "mrpt_krp_plugin/filter/see_through.h"

namespace krp {

/// How a PlaceTracker places and re-fits its places.
struct PlaceTrackerParams {
  /// On the first scan each place is moved to the best pose of a grid this far around it, in
  /// steps of refine_step_m and refine_step_deg (a place found on the matcher's grid may sit
  /// next to its best, not on it) [m], [deg].
  double first_scan_search_m = 0.3;
  double first_scan_search_deg = 3.0;
  /// Every scan re-fits each place on a 3 x 3 x 3 grid of these steps, as the rival test does,
  /// with the see-through penalty in the fit [m], [deg] ...
  double refine_step_m = 0.05;
  double refine_step_deg = 1.0;
  /// ... then on as many more such grids, each of half the last one's steps
  /// (refinedPoseOnGrids: why). 0: the first grid only.
  int finer_refinements = 3;
};

/// Throws std::invalid_argument for negative searches, steps or refinement count.
void validatePlaceTrackerParams(const PlaceTrackerParams& params);

struct TrackedPlace {
  mrpt::math::TPose2D pose;
  double log_likelihood = 0.0;  ///< summed over the scans since the first [nats]
};

/// Places weighed alike over a robot's path: each is moved by the robot's odometry, re-fitted
/// to every scan and charged that scan's log-likelihood under the filter's sensor model. The
/// path check weighs the truth this way against the places that fit its first scan nearly as
/// well, so that neither side is held on a coarser grid than the other.
class PlaceTracker {
 public:
  /// Throws as validatePlaceTrackerParams does.
  explicit PlaceTracker(PlaceTrackerParams params = {});

  /// Starts afresh from the first scan's places (kept in this order): each moved to its best
  /// pose of the first-scan grid, then weighed on `scan` (see update).
  void start(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
             const std::vector<mrpt::math::TPose2D>& places, const SeeThroughPenalty::Scan* see_through);
  /// Moves every place by the robot's odometry increment since the last scan.
  void move(const mrpt::poses::CPose2D& increment);
  /// Adds one scan's evidence to every place: re-fitted (less `see_through`'s penalty where
  /// given), and charged its log-likelihood there.
  void update(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
              const SeeThroughPenalty::Scan* see_through);

  const std::vector<TrackedPlace>& places() const { return places_; }

 private:
  PlaceTrackerParams params_;
  std::vector<TrackedPlace> places_;
};

}  // namespace krp
