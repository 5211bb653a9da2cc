// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstdint>
#include <vector>

#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/zones/zone.h"

namespace krp {

/// Automatic zoning: rooms and corridors by a distance-transform watershed, then sized
/// towards a target area (large regions split, small ones merged into a neighbour).
struct AutoZoningParams {
  double target_area_m2 = 80.0;        ///< the zone size aimed at [m^2]
  double split_above_factor = 1.6;     ///< a region larger than this x target is split
  double merge_below_factor = 0.35;    ///< a region smaller than this x target joins a neighbour
  double passage_half_width_m = 0.55;  ///< free space narrower than 2x this (doors) separates rooms [m]
  double min_island_area_m2 = 0.5;     ///< free islands smaller than this are ignored [m^2]
  double min_zone_area_m2 = 2.0;       ///< isolated pockets smaller than this get no zone [m^2]
  int max_split_rounds = 8;            ///< bound on split and enclosure passes (rings need several)
  uint64_t seed = 1;                   ///< k-means seed for splits
  CellClassParams cells;
};

/// Partitions the free space. Zones are named zone_00, zone_01, ... ordered top-left first.
/// Throws InputError if the map has no free space to zone, or for a target area that is not a
/// positive number (or factors that would merge what they split).
std::vector<Zone> autoZone(const mrpt::maps::COccupancyGridMap2D& grid, const AutoZoningParams& params = {});

}  // namespace krp
