// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/icp_refiner.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/slam/CICP.h>

#include <cmath>

#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {

IcpRefiner::IcpRefiner(const mrpt::maps::COccupancyGridMap2D& map, IcpRefineParams params) : params_(params) {
  CellClassParams cells;
  cells.min_occupied_occupancy = params_.min_occupancy;
  for (const auto& c : maskedCells(occupiedMask(map, cells)))
    map_points_.insertPoint(static_cast<float>(map.idx2x(c.x)), static_cast<float>(map.idx2y(c.y)), 0.0f);
  // MRPT builds a points map's k-d tree on its first query. Query it now, so that the tree is
  // built with the map, not inside the first relocalization after start-up: the scan that matters
  // most (35 ms more than the next ones on the warehouse map when it was built there).
  if (map_points_.size() > 0) {
    float x = 0, y = 0, distance_sq = 0;
    map_points_.kdTreeClosestPoint2D(0.0f, 0.0f, x, y, distance_sq);
  }
}

mrpt::math::TPose2D IcpRefiner::refine(const mrpt::obs::CObservation2DRangeScan& scan,
                                       const mrpt::math::TPose2D& guess) const {
  mrpt::maps::CSimplePointsMap scan_points;
  scan_points.loadFromRangeScan(scan);
  if (scan_points.size() < 3 || map_points_.size() < 3) return guess;
  mrpt::slam::CICP icp;
  icp.options.ICP_algorithm = mrpt::slam::icpClassic;
  icp.options.maxIterations = static_cast<unsigned>(params_.max_iterations);
  icp.options.thresholdDist = params_.max_correspondence_m;
  icp.options.smallestThresholdDist = params_.min_correspondence_m;
  icp.options.ALFA = params_.correspondence_shrink;
  icp.options.skip_cov_calculation = true;
  mrpt::slam::CICP::TReturnInfo info;
  const auto pdf = icp.Align(&map_points_, &scan_points, mrpt::poses::CPose2D(guess), info);
  const auto refined = pdf->getMeanVal().asTPose();
  const double shift = std::hypot(refined.x - guess.x, refined.y - guess.y);
  const double turn = std::abs(mrpt::math::wrapToPi(refined.phi - guess.phi));
  if (!std::isfinite(refined.x) || !std::isfinite(refined.y) || !std::isfinite(refined.phi) ||
      shift > params_.max_shift_m || turn > params_.max_turn_deg * M_PI / 180.0)
    return guess;
  return refined;
}

}  // namespace krp
