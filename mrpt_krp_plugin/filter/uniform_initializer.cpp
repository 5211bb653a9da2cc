// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/uniform_initializer.h"

#include <algorithm>
#include <cmath>

#include "mrpt_krp_plugin/map/occupancy_map.h"

namespace krp {

std::size_t UniformInitializer::particleCount(const mrpt::maps::COccupancyGridMap2D& map) const {
  if (params_.particles > 0) return params_.particles;
  const auto n = static_cast<std::size_t>(std::lround(params_.particles_per_m2 * freeAreaM2(map)));
  return std::clamp(n, params_.min_particles, params_.max_particles);
}

void UniformInitializer::initialize(mrpt::slam::CMonteCarloLocalization2D& pf,
                                    mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf_options,
                                    const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CSensoryFrame&) {
  pf_options.adaptiveSampleSize = false;
  auto& m = const_cast<mrpt::maps::COccupancyGridMap2D&>(map);  // MRPT's API takes a non-const pointer; it only reads
  pf.resetUniformFreeSpace(&m, params_.free_cell_min_freeness, static_cast<int>(particleCount(map)));
}

}  // namespace krp
