// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/amcl_kld_initializer.h"

#include <cmath>

namespace krp {

double AmclKldParams::mrptKldDelta() const { return 1.0 - 0.5 * std::erfc(-kld_z / std::sqrt(2.0)); }

void AmclKldInitializer::initialize(mrpt::slam::CMonteCarloLocalization2D& pf,
                                    mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf_options,
                                    const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CSensoryFrame&) {
  auto& kld = pf.options.KLD_params;
  kld.KLD_minSampleSize = static_cast<unsigned>(params_.min_particles);
  kld.KLD_maxSampleSize = static_cast<unsigned>(params_.max_particles);
  kld.KLD_epsilon = params_.kld_err;
  kld.KLD_delta = params_.mrptKldDelta();
  kld.KLD_binSize_XY = params_.bin_xy_m;
  kld.KLD_binSize_PHI = params_.bin_phi_deg * M_PI / 180.0;
  pf_options.adaptiveSampleSize = true;
  // MRPT's KLD path requires multinomial resampling; amcl starts with max_particles.
  pf_options.resamplingMethod = mrpt::bayes::CParticleFilter::prMultinomial;
  auto& m = const_cast<mrpt::maps::COccupancyGridMap2D&>(map);  // read-only use; MRPT's API is non-const
  pf.resetUniformFreeSpace(&m, params_.free_cell_min_freeness, static_cast<int>(params_.max_particles));
}

}  // namespace krp
