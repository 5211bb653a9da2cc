// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"

namespace krp {

struct ScanSimulatorParams {
  /// Ray-march step in cells. MRPT's laserScanSimulator takes a fixed number of steps of
  /// this size, so its reach is steps*size (about 0.8 x max range by default); the wrapper
  /// scales the simulated range so rays always reach the profile's max range.
  double ray_step_cells = 0.5;
  double free_threshold = 0.6;  ///< cells with p(free) above this let the ray pass [0..1]
};

/// Simulates scans of a profile with MRPT's `laserScanSimulator`, then applies the profile's
/// range noise and dropout with the project's own seeded generator (MRPT's global one
/// would make results depend on what ran before).
class ScanSimulator {
 public:
  ScanSimulator(LidarProfile profile, ScanSimulatorParams params = {});

  /// A scan taken by a robot at `robot_pose` in `world` (which may hold unmapped clutter).
  mrpt::obs::CObservation2DRangeScan::Ptr simulate(const mrpt::maps::COccupancyGridMap2D& world,
                                                   const mrpt::poses::CPose2D& robot_pose, Rng& rng) const;

  const LidarProfile& profile() const { return profile_; }

 private:
  LidarProfile profile_;
  ScanSimulatorParams params_;
};

}  // namespace krp
