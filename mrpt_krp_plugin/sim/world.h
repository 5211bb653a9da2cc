// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/sim/clutter.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"

namespace krp {

/// A simulated world: a map, its zones, the lidars to test and the clutter to add.
/// File format (`<name>.world.yaml`, paths relative to the file):
///   name: warehouse
///   map: warehouse.yaml
///   zones: warehouse.zones.yaml
///   lidar_profiles: [lds01, omni_12m, safety_270]   # built-in names, or profile files (NAME.yaml,
///                                                    # beside the world file; sim/lidar_profile_file.h)
///   default_lidar_profile: omni_12m
///   lidar_overrides: {range_noise_std_m: 0.01, dropout_probability: 0.01}   # optional
///   clutter: {boxes_per_100m2: 0.8, box_min_side_m: 0.3, box_max_side_m: 0.8,
///             pallets_per_100m2: 0.2, people_per_100m2: 0.4, placement_clearance_m: 0.2}
struct World {
  std::string name;
  std::string map_path;    ///< resolved
  std::string zones_path;  ///< resolved
  std::vector<std::string> lidar_profiles;
  std::string default_lidar_profile;
  double range_noise_std_m = -1.0;     ///< < 0: keep each profile's own [m]
  double dropout_probability = -1.0;   ///< < 0: keep each profile's own
  ClutterParams clutter;
  /// Trials start inside the zone of this name (of the zones file); empty: anywhere. For scenes
  /// that put the robot where the models were not trained (scripts/bench_unseen_zone.sh).
  std::string trial_start_zone;

  /// A profile of this world with the world's overrides applied; InputError if not listed.
  LidarProfile lidar(const std::string& profile_name) const;
  /// A user's profile file as it is (listed or not: their own scanner in this world), else the
  /// listed profile of that name, as lidar() gives it.
  LidarProfile lidarOrProfileFile(const std::string& name_or_file) const;
};

/// Reads a world file; InputError for unknown keys, bad values, unknown profiles.
World readWorld(const std::string& path);

/// Writes a world file (map and zone paths written relative to its folder), atomically.
void writeWorld(const World& world, const std::string& path);

}  // namespace krp
