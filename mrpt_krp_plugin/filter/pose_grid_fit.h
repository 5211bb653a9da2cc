// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "mrpt_krp_plugin/filter/see_through.h"

namespace krp {

/// A regular grid of poses around a centre: (2 half_cells_xy + 1)^2 positions times
/// (2 half_cells_phi + 1) headings.
struct PoseGrid {
  double step_m = 0.05;
  double step_deg = 1.0;
  int half_cells_xy = 1;
  int half_cells_phi = 1;
};

struct PoseGridFit {
  mrpt::math::TPose2D pose;  ///< the grid's best pose (the first of equals, x, then y, then heading ascending)
  double score = 0.0;        ///< its log-likelihood, less `charge`'s penalty when given [nats]
};

/// The pose of `grid` around `centre` where `scan` is likeliest under `map`'s likelihood options,
/// less the see-through penalty when `charge` is given: the re-fit a rival test gives each side,
/// and, on a wider grid, the path check's placing of a matcher solution.
PoseGridFit bestPoseOnGrid(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
                           const mrpt::math::TPose2D& centre, const PoseGrid& grid,
                           const SeeThroughPenalty::Scan* charge = nullptr);

/// bestPoseOnGrid on `grid` around `start`, then on `finer_refinements` more grids, each of half
/// the last one's steps around the last one's best (so that it spans the half step either side of
/// it, where the optimum lies). The likelihood field is sharp: a pose held a few centimetres or
/// half a degree off its best, as a 5 cm / 1 deg grid holds it, loses several nats a scan at
/// 12 m ranges, more than the scans of two look-alike places differ by. 0: `grid` only.
PoseGridFit refinedPoseOnGrids(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
                               const mrpt::math::TPose2D& start, PoseGrid grid, int finer_refinements,
                               const SeeThroughPenalty::Scan* charge = nullptr);

}  // namespace krp
