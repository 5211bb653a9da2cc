// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

namespace krp {

struct IcpRefineParams {
  int max_iterations = 40;
  double max_correspondence_m = 1.0;       ///< first pairing distance; a hypothesis farther off stays off [m]
  double min_correspondence_m = 0.1;       ///< the pairing distance shrinks to this [m]
  double correspondence_shrink = 0.5;      ///< factor applied each time ICP converges at a distance
  double max_shift_m = 1.5;                ///< a refinement that moves the pose more than this is refused [m]
  double max_turn_deg = 20.0;              ///< ... or turns it more than this [deg]
  double min_occupancy = 0.65;             ///< map cells above this become ICP's reference points [0..1]
};

/// Refines a pose hypothesis by ICP of the scan against the map's obstacle cells (MRPT's CICP,
/// classic point-to-point). The reference point cloud and its k-d tree are built once, by the
/// constructor (a copy would build its tree again on its first refine: MRPT's copies drop it).
class IcpRefiner {
 public:
  IcpRefiner(const mrpt::maps::COccupancyGridMap2D& map, IcpRefineParams params = {});

  /// The refined pose, or `guess` when ICP diverged or moved further than allowed.
  mrpt::math::TPose2D refine(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& guess) const;

 private:
  IcpRefineParams params_;
  mrpt::maps::CSimplePointsMap map_points_;
};

}  // namespace krp
