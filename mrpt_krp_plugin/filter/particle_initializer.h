// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>

#include <optional>
#include <string>

#include "mrpt_krp_plugin/filter/kld_sample_size.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_ranking.h"

namespace krp {

/// How the filter starts when the robot knows nothing of its pose. Every method the bench
/// compares (uniform, AMCL-style KLD, and later the learned seeded prior) implements this.
class ParticleInitializer {
 public:
  virtual ~ParticleInitializer() = default;

  /// Short name used by the bench and the apps (`uniform-mcl`, `amcl-kld`, ...).
  virtual std::string name() const = 0;

  /// Fills `pf` with the prior and sets its sample-size options (`pf.options.KLD_params`,
  /// `pf_options.adaptiveSampleSize`). `first` is the first observation, which a seeded
  /// initializer uses; uniform ones ignore it.
  virtual void initialize(mrpt::slam::CMonteCarloLocalization2D& pf, mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf_options,
                          const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CSensoryFrame& first) = 0;

  /// After initialize(): how the filter sizes its set at each of its own resamplings. Empty
  /// (the default): the start's count stays to the end, as in MRPT's fixed-size MCL; given,
  /// KLD sampling picks the count, never above the start's. MRPT's own KLD path
  /// (`pf_options.adaptiveSampleSize`) does not ask.
  virtual std::optional<KldResampling> kldResampling() const { return std::nullopt; }

  /// For a filter it started that is still unsure of its pose (LaterScanSeedingParams): the
  /// hypotheses of a later scan, best first. Empty (the default): it has none to offer, as the
  /// uniform starts have not.
  virtual std::optional<Ranking> laterHypotheses(const mrpt::obs::CSensoryFrame& /*frame*/) { return std::nullopt; }
};

}  // namespace krp
