// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/pose_grid_fit.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <limits>

namespace krp {

PoseGridFit bestPoseOnGrid(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
                           const mrpt::math::TPose2D& centre, const PoseGrid& grid, const SeeThroughPenalty::Scan* charge) {
  const double step_rad = grid.step_deg * M_PI / 180.0;
  PoseGridFit best{centre, -std::numeric_limits<double>::infinity()};
  for (int dx = -grid.half_cells_xy; dx <= grid.half_cells_xy; ++dx)
    for (int dy = -grid.half_cells_xy; dy <= grid.half_cells_xy; ++dy)
      for (int dphi = -grid.half_cells_phi; dphi <= grid.half_cells_phi; ++dphi) {
        const mrpt::math::TPose2D p(centre.x + dx * grid.step_m, centre.y + dy * grid.step_m,
                                    mrpt::math::wrapToPi(centre.phi + dphi * step_rad));
        double score = map.computeObservationLikelihood(scan, mrpt::poses::CPose3D(mrpt::poses::CPose2D(p)));
        if (charge) score -= charge->nats(p);
        if (score > best.score) best = {p, score};
      }
  return best;
}

PoseGridFit refinedPoseOnGrids(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CObservation2DRangeScan& scan,
                               const mrpt::math::TPose2D& start, PoseGrid grid, int finer_refinements,
                               const SeeThroughPenalty::Scan* charge) {
  PoseGridFit fit = bestPoseOnGrid(map, scan, start, grid, charge);
  for (int level = 0; level < finer_refinements; ++level) {
    grid.step_m /= 2.0;
    grid.step_deg /= 2.0;
    fit = bestPoseOnGrid(map, scan, fit.pose, grid, charge);
  }
  return fit;
}

}  // namespace krp
