// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstdint>
#include <functional>

#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/trial.h"

namespace krp {

/// What krp-bench-see-through measures: the filter's see-through charge of a particle cloud
/// (SeeThroughPenalty::Scan::count over every particle, as a filter update does) with the rays
/// marched side by side against one at a time (countOneRayAtATime), on the same scans and
/// particles, taking turns at going first, so that the ratio survives a noisy machine.
struct SeeThroughSpeedParams {
  int scans = 30;         ///< first scans of simulated trials, one per trial seed
  uint64_t seed = 1;      ///< trial i uses seed + i
  int particles = 500;    ///< drawn around the true pose, as a seeded prior's cloud
  double spread_m = 0.2;  ///< their std around it, position [m]
  double spread_deg = 5.0;  ///< ... and heading [deg]
  int repeats = 5;        ///< each cloud charged this many times by each way, the fastest kept
  MclParams filter;       ///< its sensor model (decimation) and see-through settings
  TrialParams trial;      ///< where the scans come from (clutter, scanner noise)
};

/// Both ways over every scan.
struct SeeThroughSpeed {
  int scans = 0;
  long long particle_charges = 0;     ///< particles charged per way, over every scan
  double median_ms_one_at_a_time = 0.0;  ///< thread CPU per cloud [ms]
  double median_ms_side_by_side = 0.0;
  double median_ratio = 0.0;  ///< median over scans of one-at-a-time / side-by-side time
  double total_ratio = 0.0;   ///< total one-at-a-time time / total side-by-side time
  double mean_seen_through = 0.0;  ///< beams seen through per particle, mean
  int checked_beams = 0;           ///< beams checked per particle (the last scan's)
  long long differing = 0;         ///< particles whose two counts differed (must be 0)
};

/// Throws std::invalid_argument for scans, particles or repeats below 1 or a negative spread.
SeeThroughSpeed measureSeeThroughSpeed(const mrpt::maps::COccupancyGridMap2D& map, const LidarProfile& lidar,
                                       const SeeThroughSpeedParams& params,
                                       const std::function<void()>& on_scan = {});

}  // namespace krp
