// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <memory>

namespace krp {

/// The scan likelihood the filter weighs particles with (MRPT's likelihood field).
struct SensorModelParams {
  int decimation = 4;            ///< use every n-th beam
  double std_hit_m = 0.20;       ///< likelihood-field sigma [m]
  double max_corr_distance_m = 0.5;  ///< distances beyond this count as this [m]
  double z_hit = 0.95;           ///< weight of the hit model [0..1]
  double z_random = 0.05;        ///< weight of random returns [0..1]

  bool operator==(const SensorModelParams& o) const {
    return decimation == o.decimation && std_hit_m == o.std_hit_m && max_corr_distance_m == o.max_corr_distance_m &&
           z_hit == o.z_hit && z_random == o.z_random;
  }
  bool operator!=(const SensorModelParams& o) const { return !(*this == o); }
};

/// Sets `map`'s likelihood options to this sensor model (MRPT keeps them, and a cache, in the map).
void useSensorModel(mrpt::maps::COccupancyGridMap2D& map, const SensorModelParams& sensor);

/// A map ready to weigh scans with one sensor model: its likelihood field is computed for every
/// cell, once, as amcl does when it loads a map. MRPT otherwise fills its cache cell by cell
/// during the first updates, which charges map loading to the first relocalization (more to a
/// filter whose particles cover the whole map than to one seeded at a few places).
struct SensorModelMap {
  std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> grid;  ///< sensor model set, cache filled
  SensorModelParams sensor;                                      ///< the model the cache holds
};

/// Sets `sensor` on `map` and computes its likelihood field for every cell with MRPT's own code,
/// so the values are those MRPT would compute on demand.
void fillLikelihoodField(mrpt::maps::COccupancyGridMap2D& map, const SensorModelParams& sensor);

/// A copy of `map` with fillLikelihoodField applied, to be shared by many filters.
SensorModelMap prepareSensorModelMap(const mrpt::maps::COccupancyGridMap2D& map, const SensorModelParams& sensor);

}  // namespace krp
