// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/TPose2D.h>

#include <cstddef>
#include <vector>

#include "mrpt_krp_plugin/filter/filter_spread.h"

namespace krp {

/// KLD sampling's sample size (Fox 2003), as amcl sizes its particle set: enough particles that,
/// with probability z, the set's histogram is within `epsilon` (KL divergence) of the posterior's,
/// given how many histogram bins the set occupies. A converged filter occupies a few bins and
/// needs a few hundred particles; one spread over a building needs its whole cap.
struct KldSampleSizeParams {
  double epsilon = 0.01;  ///< amcl `kld_err`
  /// amcl `kld_z`, used as the normal quantile itself, as amcl does (see AmclKldParams).
  double z = 0.99;
  double bin_xy_m = 0.5;      ///< amcl's histogram bins [m]
  double bin_phi_deg = 10.0;  ///< [deg]
};

/// When a filter's resampling sizes its set by KLD sampling (a filter that started uniform).
struct KldResamplingParams {
  KldSampleSizeParams size;
  /// Sized by KLD only once the weighted set is this concentrated: from a uniform start the first
  /// scans' weights are so peaked that KLD would cut a still-undecided set to its floor, dropping
  /// the places that later scans might favour. Until then the set keeps (or regains) its start's
  /// count.
  ConcentrationThresholds only_once_concentrated;
  /// ...and only once it has been so at this many resamplings in a row: with a short-range lidar
  /// one scan can gather a uniform start on a wrong place, which the next scans would spread
  /// again if the set still had the particles to find the truth [1 or more]. 5: of the lds01
  /// profile's 200 uniform starts (`seeded-keypoints-only`, office, seeds 1 and 2) that the
  /// fixed count got right, 1 lost 2 + 1, 3 lost 0 + 1, 5 none; on Willow's six uniform starts
  /// 5 still halves their CPU (docs/results.md, "A uniform start that shrinks").
  int concentrated_resamplings = 5;
};

/// The KLD bound for `occupied_bins` bins (0 for one bin or none: any sample describes it).
std::size_t kldBound(std::size_t occupied_bins, double epsilon, double z);

/// How many of `draws` (poses drawn from the posterior, in random order) KLD sampling keeps:
/// the shortest prefix that is at least the bound for the bins it occupies and at least
/// `min_particles`; all of them when no prefix is. The caller's draws are its cap.
std::size_t kldSampleCount(const std::vector<mrpt::math::TPose2D>& draws, const KldSampleSizeParams& params,
                           std::size_t min_particles);

/// What an initializer asks of the filter's resampling: KLD sizing with `params`, never below
/// `min_particles` (the seeded start's own floor, so that a filter that shrank has as many
/// particles as one the relocalizer seeded).
struct KldResampling {
  KldResamplingParams params;
  std::size_t min_particles = 0;
};

}  // namespace krp
