// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstdint>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/zones/zone.h"

namespace krp {

/// A generated world before it is written: its map and zones.
struct BuiltWorld {
  std::string name;
  mrpt::maps::COccupancyGridMap2D map;
  std::vector<Zone> zones;
  std::string trial_start_zone;  ///< World::trial_start_zone of the world file (empty: none)
};

constexpr double kWorldResolutionM = 0.05;  ///< cell size of every generated world [m]

/// Rooms off a corridor, two zones (left and right wing), in the spirit of the thesis's
/// Willow Garage set-up. Room widths, doors and furniture vary with `seed`.
BuiltWorld buildOfficeTwoZone(uint64_t seed);

/// A hall with two blocks of identical rack rows and aisles, 8 zones: deliberately
/// repetitive, the case where global localization picks the wrong aisle.
BuiltWorld buildWarehouse(uint64_t seed);

/// A multi-room floor (> 3000 m^2 free) with corridors, zoned automatically (>= 12 zones).
BuiltWorld buildLargeFloor(uint64_t seed);

/// Degenerate scenes for the robustness bench (scripts/bench_degenerate.sh): a 60 x 2.4 m
/// featureless corridor and a 40 x 30 m empty hall, two zones each. The seed is unused.
BuiltWorld buildCorridor(uint64_t seed);
BuiltWorld buildEmptyHall(uint64_t seed);

/// office_two_zone (same seed, same rooms, same two zones) with a 16 x 22 m open-plan wing
/// beyond its east wall, a third zone `unseen_wing` that models trained on office_two_zone never
/// saw; its world file starts every trial there (scripts/bench_unseen_zone.sh).
BuiltWorld buildOfficeUnseenWing(uint64_t seed);

/// The names accepted by `buildWorld`.
const std::vector<std::string>& worldNames();
BuiltWorld buildWorld(const std::string& name, uint64_t seed);

/// An axis-aligned zone covering the cells of [x0, x1) x [y0, y1): its corners sit on the
/// centres of the first and last cells, so neighbouring rectangles never claim the same cell.
Zone rectangleZone(const std::string& name, double x0, double y0, double x1, double y1, double resolution_m);

}  // namespace krp
