// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>

#include "mrpt_krp_plugin/filter/particle_initializer.h"

namespace krp {

/// `amcl-kld`: AMCL's global localization as ROS 1 amcl ships it: uniform start, then KLD
/// adaptive sample size. Defaults are amcl's (min_particles 100, max_particles 5000,
/// kld_err 0.01, kld_z 0.99) and its 0.5 m / 10 deg histogram bins.
struct AmclKldParams {
  std::size_t min_particles = 100;
  std::size_t max_particles = 5000;
  double kld_err = 0.01;        ///< amcl `kld_err` (MRPT KLD_epsilon)
  double kld_z = 0.99;          ///< amcl `kld_z`, used by amcl as the normal quantile itself
  double bin_xy_m = 0.5;        ///< [m]
  double bin_phi_deg = 10.0;    ///< [deg]
  double free_cell_min_freeness = 0.7;

  /// MRPT computes chi2inv(1 - KLD_delta); amcl plugs z straight into the Wilson-Hilferty
  /// formula. The same bound needs KLD_delta = 1 - Phi(z).
  double mrptKldDelta() const;
};

class AmclKldInitializer : public ParticleInitializer {
 public:
  explicit AmclKldInitializer(AmclKldParams params = {}, std::string name = "amcl-kld")
      : params_(params), name_(std::move(name)) {}
  std::string name() const override { return name_; }
  void initialize(mrpt::slam::CMonteCarloLocalization2D& pf, mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf_options,
                  const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CSensoryFrame& first) override;

 private:
  AmclKldParams params_;
  std::string name_;
};

}  // namespace krp
