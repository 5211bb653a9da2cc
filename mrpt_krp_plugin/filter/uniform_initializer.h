// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>

#include "mrpt_krp_plugin/filter/particle_initializer.h"

namespace krp {

/// `uniform-mcl`: a fixed number of particles spread uniformly over the free space, every
/// heading equally likely; MRPT's own global-localization start.
struct UniformInitParams {
  double particles_per_m2 = 40.0;  ///< sets N from the free area when `particles` is 0 [1/m^2]
  std::size_t particles = 0;       ///< fixed N; 0 = from the density
  std::size_t min_particles = 1000;     ///< floor for the density rule
  std::size_t max_particles = 200000;   ///< cap for the density rule
  double free_cell_min_freeness = 0.7;  ///< MRPT's threshold for a free cell [0..1]
};

class UniformInitializer : public ParticleInitializer {
 public:
  explicit UniformInitializer(UniformInitParams params = {}) : params_(params) {}
  std::string name() const override { return "uniform-mcl"; }
  void initialize(mrpt::slam::CMonteCarloLocalization2D& pf, mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf_options,
                  const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CSensoryFrame& first) override;

  /// The N this initializer uses on `map`.
  std::size_t particleCount(const mrpt::maps::COccupancyGridMap2D& map) const;

 private:
  UniformInitParams params_;
};

}  // namespace krp
