// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/place_tracker.h"

#include <cmath>
#include <stdexcept>

#include "mrpt_krp_plugin/filter/pose_grid_fit.h"

namespace krp {

namespace {

/// Half the cells of a grid of `step` reaching `extent` on either side (none for a zero step).
int halfCells(double extent, double step) { return step > 0.0 ? static_cast<int>(std::floor(extent / step)) : 0; }

}  // namespace

void validatePlaceTrackerParams(const PlaceTrackerParams& params) {
  if (!(params.first_scan_search_m >= 0.0 && params.first_scan_search_deg >= 0.0 && params.refine_step_m >= 0.0 &&
        params.refine_step_deg >= 0.0))
    throw std::invalid_argument("PlaceTracker: searches and refinement steps must be >= 0");
  if (params.finer_refinements < 0) throw std::invalid_argument("PlaceTracker: finer_refinements must be 0 or more");
}

PlaceTracker::PlaceTracker(PlaceTrackerParams params) : params_(params) { validatePlaceTrackerParams(params_); }

void PlaceTracker::start(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
                         const std::vector<mrpt::math::TPose2D>& places, const SeeThroughPenalty::Scan* see_through) {
  const PoseGrid grid{params_.refine_step_m, params_.refine_step_deg,
                      halfCells(params_.first_scan_search_m, params_.refine_step_m),
                      halfCells(params_.first_scan_search_deg, params_.refine_step_deg)};
  places_.clear();
  for (const auto& p : places) places_.push_back({bestPoseOnGrid(map, scan, p, grid, see_through).pose, 0.0});
  update(map, scan, see_through);
}

void PlaceTracker::move(const mrpt::poses::CPose2D& increment) {
  for (auto& p : places_) p.pose = (mrpt::poses::CPose2D(p.pose) + increment).asTPose();
}

void PlaceTracker::update(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
                          const SeeThroughPenalty::Scan* see_through) {
  const PoseGrid grid{params_.refine_step_m, params_.refine_step_deg, 1, 1};
  for (auto& p : places_) {
    const auto fit = refinedPoseOnGrids(map, scan, p.pose, grid, params_.finer_refinements, see_through);
    p.pose = fit.pose;
    p.log_likelihood += fit.score;
  }
}

}  // namespace krp
