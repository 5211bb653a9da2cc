// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/sim/clutter.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"

namespace krp {

/// The thesis's scenario generation: what changes between the map and what the robot sees.
/// Every effect scales with `strength`; strength 0 switches all of them off (the thesis's
/// "without scenario generation"), 1 is the default, larger is harsher.
struct ScenarioParams {
  double strength = 1.0;
  double clutter_scale = 1.0;          ///< x the world's clutter densities, at strength 1
  double occlusion_probability = 0.3;  ///< chance that something close blocks part of the view, at strength 1
  double occlusion_max_sector_deg = 60.0;  ///< widest blocked sector [deg]
  double occlusion_min_range_m = 0.3;  ///< the blocker's distance range [m]
  double occlusion_max_range_m = 1.2;  ///< [m]
  double extra_range_noise_m = 0.02;   ///< added to the profile's range noise, at strength 1 [m]
  double extra_dropout = 0.03;         ///< added to the profile's dropout, at strength 1
  double moved_furniture_fraction = 0.0;  ///< share of mapped furniture moved (the changed-environment split)
  double furniture_max_area_m2 = 4.0;  ///< occupied blobs up to this size count as movable furniture [m^2]
  double furniture_max_shift_m = 1.0;  ///< how far moved furniture goes [m]

  /// The changed-environment variant: three times the clutter and occlusion, and a third of
  /// the furniture moved.
  ScenarioParams changedEnvironment() const;
};

/// The world as the robot meets it: the map plus clutter (and moved furniture), per `params`.
mrpt::maps::COccupancyGridMap2D scenarioWorld(const mrpt::maps::COccupancyGridMap2D& map, const ClutterParams& clutter,
                                              const ScenarioParams& params, Rng& rng);

/// The lidar with the scenario's extra noise and dropout.
LidarProfile scenarioLidar(const LidarProfile& lidar, const ScenarioParams& params);

/// With the scenario's probability, replaces a random sector of the scan by returns from a
/// close blocker (a person or a box next to the robot). Returns true if it did.
bool applyOcclusion(mrpt::obs::CObservation2DRangeScan& scan, const ScenarioParams& params, Rng& rng);

}  // namespace krp
