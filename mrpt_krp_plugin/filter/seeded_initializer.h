// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "mrpt_krp_plugin/filter/free_cells.h"
#include "mrpt_krp_plugin/filter/particle_initializer.h"
#include "mrpt_krp_plugin/filter/uniform_initializer.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_ranking.h"
#include "mrpt_krp_plugin/relocalize/relocalization_times.h"

namespace krp {

struct SeededInitParams {
  /// Around each hypothesis, before the confidence split. 250 kept the office's success of 300
  /// (krp-bench --seeded-particles-per-hypothesis, 100 trials, seeds 1 and 7: 99 % and 100 %
  /// either way): the clouds' minimum spread (min_std_*) keeps them alive under the motion noise,
  /// not their count.
  std::size_t particles_per_hypothesis = 250;
  std::size_t min_particles = 500;             ///< total, uniform share included
  std::size_t max_particles = 5000;            ///< total cap
  /// Set: instead of particles_per_hypothesis, the count comes from the hypotheses' spread, by
  /// KLD sampling of the mixture itself (Fox 2003, with these bins and bounds): as many draws as
  /// a histogram of the prior needs, so a wide or many-headed prior gets more particles than one
  /// tight pose; min_particles and max_particles still bound the total. Unset by default: measured
  /// against the fixed count (the `seeded-spread-count` method of krp-bench, reports/spread_count),
  /// it bought nothing there.
  std::optional<KldSampleSizeParams> count_from_spread;
  /// Share of the particles spread uniformly over the free space, so that a wrong hypothesis
  /// stays recoverable. Never zero by default; 0 gives the `seeded-no-uniform` method [0..1).
  double uniform_fraction = 0.05;
  /// The alignment's covariance is clamped to these standard deviations: below the minimum the
  /// cloud would be too narrow for the filter's motion noise to keep alive, above the maximum a
  /// hypothesis is no longer concentrated.
  double min_std_xy_m = 0.15, max_std_xy_m = 1.0;
  double min_std_yaw_deg = 3.0, max_std_yaw_deg = 20.0;
  /// With no hypothesis at all, the filter starts as uniform MCL with these settings.
  UniformInitParams fallback;
  /// ...and then sizes its set by KLD sampling at each resampling, so that once it converges it
  /// tracks with a seeded start's few hundred particles instead of the tens of thousands that
  /// cover the map (unset: the uniform count stays to the end). A seeded start is already
  /// concentrated and capped at max_particles; its count stays fixed. Never below min_particles.
  std::optional<KldResamplingParams> fallback_shrinks = KldResamplingParams{};
  double free_cell_min_freeness = 0.7;  ///< a map cell with p(free) above this is free [0..1]
  uint64_t seed = 1;
};

/// What the last initialize() did, for reports.
struct SeedingRecord {
  Ranking ranking;
  std::size_t particles = 0, uniform_particles = 0;
  bool fell_back_to_uniform = false;
  /// Thread CPU time from the scan to the drawn prior: relocalization and sampling [s].
  double cpu_s = 0.0;
  /// Where the relocalization's time went, when the source says (the learned relocalizer).
  std::optional<RelocalizationTimes> stage_times;
};

/// A hypothesis source's answer with the time of each of its stages, for reports.
struct TimedRanking {
  Ranking ranking;
  std::optional<RelocalizationTimes> stage_times;  ///< empty: the source does not break its time down
};

/// `seeded`: the relocalizer's hypotheses become a Gaussian mixture (particles split by
/// confidence; when the relocalizer is unsure, the hypotheses still share the particles in
/// proportion to their confidence) plus a uniform share over free space. No hypothesis at all
/// means uniform MCL.
class SeededInitializer : public ParticleInitializer {
 public:
  /// Turns the first scan into ranked hypotheses (a Relocalizer in the apps, a stub in tests).
  using HypothesisSource = std::function<Ranking(const mrpt::obs::CObservation2DRangeScan&)>;
  /// The same, saying where its time went (SeedingRecord::stage_times).
  using TimedHypothesisSource = std::function<TimedRanking(const mrpt::obs::CObservation2DRangeScan&)>;

  SeededInitializer(HypothesisSource source, SeededInitParams params = {}, std::string name = "seeded");
  SeededInitializer(TimedHypothesisSource source, SeededInitParams params = {}, std::string name = "seeded");
  std::string name() const override { return name_; }
  void initialize(mrpt::slam::CMonteCarloLocalization2D& pf, mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf_options,
                  const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CSensoryFrame& first) override;

  std::optional<KldResampling> kldResampling() const override;
  /// The source's answer for the frame's scan (none without one); lastSeeding() stays the
  /// first scan's.
  std::optional<Ranking> laterHypotheses(const mrpt::obs::CSensoryFrame& frame) override;

  const std::optional<SeedingRecord>& lastSeeding() const { return last_; }

  /// The free cells of the map this initializer will seed on, built once by whoever holds the
  /// map (FreeCells): the uniform share is drawn from them instead of from the map's cells read
  /// afresh at each seeding. Cells built from another map, or with another free_cell_min_freeness,
  /// are not used (the map's cells are read afresh as without them); the particles are the same
  /// either way.
  void useFreeCells(std::shared_ptr<const FreeCells> free_cells) { free_cells_ = std::move(free_cells); }

 private:
  TimedHypothesisSource source_;
  SeededInitParams params_;
  std::string name_;
  std::optional<SeedingRecord> last_;
  std::shared_ptr<const FreeCells> free_cells_;
};

}  // namespace krp
