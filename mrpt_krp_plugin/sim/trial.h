// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <vector>

#include "mrpt_krp_plugin/sim/clutter.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"

namespace krp {

/// Odometry error: standard deviations grow with the motion, as in a differential drive.
struct OdometryNoiseParams {
  double xy_std_per_m = 0.03;     ///< translation error per metre travelled [m/m]
  double phi_std_per_rad = 0.05;  ///< rotation error per radian turned [rad/rad]
  double phi_std_per_m = 0.02;    ///< rotation error per metre travelled [rad/m]
};

/// How a kidnapped-robot trial is generated.
struct TrialParams {
  int steps = 40;                   ///< motion steps after the first scan
  double step_length_m = 0.2;       ///< [m]
  double max_turn_deg = 15.0;       ///< heading change per step, uniform in +-this [deg]
  double clearance_m = 0.35;        ///< the robot keeps this far from anything (clutter included) [m]
  int max_step_attempts = 24;       ///< headings tried before turning in place
  /// The robot starts inside this polygon (grid-frame metres); empty: anywhere with clearance.
  /// Lets a bench put every trial in one part of a map (a zone the models never saw).
  std::vector<mrpt::math::TPoint2D> start_region;
  OdometryNoiseParams odometry;
  ClutterParams clutter;
  ScanSimulatorParams scanner;
};

/// One simulated kidnap: the robot wakes at `truth[0]` knowing nothing and moves; step 0
/// has no motion. `odometry[i]` is the noisy increment from step i-1 to i (identity for 0).
struct Trial {
  uint64_t seed = 0;
  std::vector<mrpt::math::TPose2D> truth;
  std::vector<mrpt::poses::CPose2D> odometry;
  std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
  std::vector<double> distance_m;  ///< true distance travelled up to each step [m]
};

/// Generates a trial against `map` (clutter is added to the simulation copy only).
/// Deterministic in `seed`. Throws InputError if the map has no pose with the clearance (inside
/// `start_region` when one is given).
Trial generateTrial(const mrpt::maps::COccupancyGridMap2D& map, const LidarProfile& lidar, const TrialParams& params,
                    uint64_t seed);

/// A robot tracked along `before`, then carried (kidnapped) to where `after` starts: the step
/// across has no odometry (the wheels did not turn) and the carried distance is not counted.
/// The kidnap is at index `before.truth.size()`. Keeps `before`'s seed.
Trial kidnapTrial(const Trial& before, const Trial& after);

}  // namespace krp
