// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>

#include <deque>
#include <memory>
#include <optional>

#include "mrpt_krp_plugin/filter/kidnap_detector.h"
#include "mrpt_krp_plugin/filter/later_scan_seeding.h"
#include "mrpt_krp_plugin/filter/look_alike_guard.h"
#include "mrpt_krp_plugin/filter/particle_initializer.h"
#include "mrpt_krp_plugin/filter/scan_history.h"
#include "mrpt_krp_plugin/filter/see_through.h"
#include "mrpt_krp_plugin/filter/sensor_model.h"
#include "mrpt_krp_plugin/relocalize/scan_fit.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"

namespace krp {

struct MclParams {
  SensorModelParams sensor;
  double resample_below_ess = 0.5;  ///< systematic resampling when ESS/N drops below this [0..1]
  uint32_t seed = 1;                ///< MRPT's global generator is reseeded with this
  KidnapDetectorParams kidnap;      ///< re-initialize by itself when the tracked pose stops fitting
  /// Beams returning from beyond a mapped obstacle are charged against the particle, and
  /// against a look-alike weighed by the guard, on top of the likelihood field.
  SeeThroughParams see_through;
  /// While unsure of its pose, the filter relocalizes later scans with its initializer and gives
  /// their hypotheses particles (off by default).
  LaterScanSeedingParams later_scans;
};

/// One filter update's outcome.
struct MclEstimate {
  mrpt::math::TPose2D mean;
  /// The particles' covariance; widened to cover `ambiguous_with` when the guard found one, so
  /// that whoever reads only the covariance sees an unsettled pose.
  mrpt::math::CMatrixDouble33 cov;
  /// Particles this update weighed on its scan: a resampling that ends the update may leave
  /// fewer for the next one (KLD sizing), never more than the start's.
  std::size_t particles = 0;
  double cpu_s = 0.0;  ///< thread CPU time of this update (localization code only) [s]
  /// Scan returns explained at the mean (ScanFit); -1 when neither kidnap detection nor the
  /// guard's fit floor needed it.
  double fit_fraction = -1.0;
  /// The filter has converged, but fewer of the scan's returns than the guard's
  /// min_fit_fraction are explained at the mean: `cov` is widened so the pose reads unsettled.
  bool scan_unexplained = false;
  bool initialized = false;    ///< the initializer ran at this update (the first, or after a kidnap)
  bool kidnap_detected = false;  ///< this update completed a kidnap: the next one re-initializes
  bool look_alike_found = false;  ///< the filter had converged and the guard moved particles to a look-alike place
  /// The filter has converged, but this place fit a scan nearly as well (LookAlikeGuard's
  /// ambiguity_margin) and the scans since have not yet told the two apart (RivalTest): the
  /// mean is one of two candidates, not yet a pose to drive on.
  std::optional<mrpt::math::TPose2D> ambiguous_with;
  /// Whole-map look-alike searches the guard ran in this update, and their thread CPU time (part
  /// of cpu_s) [s]: on a large map with a long-range scanner most of the filter's cost, which
  /// LookAlikeGuardParams::recheck_every_updates trades against how soon a look-alike is seen.
  int look_alike_searches = 0;
  double look_alike_search_cpu_s = 0.0;
  /// Of those searches, the ones that ran out of LookAlikeGuardParams::max_search_nodes with
  /// nothing found: a look-alike may exist that they did not reach.
  int look_alike_searches_unfinished = 0;
  /// The filter has converged, but no look-alike search since then has finished within the
  /// guard's node budget: nothing rules out a look-alike place, and with the guard's
  /// unverified_is_unsettled `cov` is widened so the pose reads unsettled.
  bool look_alike_unverified = false;
  /// A look-alike search paused at the guard's max_nodes_per_update and goes on at the next
  /// update (the estimate reads unverified meanwhile, unless a search since convergence finished).
  bool look_alike_search_pending = false;
  /// The filter was unsure of its pose, and this update's scan was relocalized (LaterScanSeedingParams).
  bool later_scan_relocalized = false;
  int later_scan_hypotheses_seeded = 0;  ///< of that scan's hypotheses, those given particles
};

/// MRPT's CMonteCarloLocalization2D driven step by step, with the start chosen by a
/// ParticleInitializer.
///
/// MRPT 2.5.8's fixed-size resampling inside CParticleFilter::executeOn does not reset the
/// weights afterwards, so they compound over resamplings; this class disables that path
/// (BETA = 0) and resamples itself (systematic, weights reset) when ESS/N < threshold, keeping
/// the count, or choosing it by KLD sampling when the initializer asks (kldResampling). MRPT's
/// KLD path resamples inside its adaptive proposal and is left as it is.
class MclLocalizer {
 public:
  /// Prepares its own copy of `map` for `params.sensor` (prepareSensorModelMap: the likelihood
  /// field of the whole map is computed here, not in the first updates).
  MclLocalizer(std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map, std::shared_ptr<ParticleInitializer> init,
               MclParams params = {});
  /// Starts from a map prepared once for many filters; `map.sensor` must be `params.sensor`
  /// (std::invalid_argument otherwise: the cache would hold another model's likelihoods).
  MclLocalizer(const SensorModelMap& map, std::shared_ptr<ParticleInitializer> init, MclParams params = {});

  /// First call initializes from the step's observation, then updates with it; so does the
  /// call after a detected kidnap.
  MclEstimate update(const RawlogStep& step);

  /// Checks the converged filter for a look-alike place (LookAlikeGuard); null: no check.
  void setLookAlikeGuard(std::shared_ptr<const LookAlikeGuard> guard);

  /// The next update runs the initializer again (a user asked to relocalize).
  void reinitialize() { initialized_ = false; }
  bool isInitialized() const { return initialized_; }

  std::size_t particleCount() const { return pf_.size(); }
  const mrpt::slam::CMonteCarloLocalization2D& particles() const { return pf_; }

 private:
  struct OwnMap {
    std::shared_ptr<mrpt::maps::COccupancyGridMap2D> grid;  ///< this filter's copy, sensor model set, field filled
  };
  MclLocalizer(OwnMap map, std::shared_ptr<ParticleInitializer> init, MclParams params);
  void resampleSystematicIfNeeded();
  /// The guard's check of a converged filter (searches, or weighs the rival under test);
  /// true when particles were moved. `increment`: the robot's odometry since the last update;
  /// `see_through`: the scan's see-through penalty, null when the filter has none.
  bool guardConvergence(const mrpt::obs::CObservation2DRangeScan& scan, const SeeThroughPenalty::Scan* see_through,
                        const mrpt::math::TPose2D& mean, const mrpt::math::CMatrixDouble33& cov,
                        const mrpt::poses::CPose2D& increment);
  /// The guard's search for a look-alike of `mean`, repeated while the ones found lose at once,
  /// `searches` times at most; true when particles were moved. `fresh`: the filter converged at
  /// this update; `after_loss`: a look-alike has just lost its test, so this looks for the next.
  bool searchForLookAlike(const mrpt::obs::CObservation2DRangeScan& scan, const SeeThroughPenalty::Scan* see_through,
                          const mrpt::math::TPose2D& mean, const mrpt::poses::CPose2D& increment, bool fresh,
                          int searches, bool after_loss);
  /// The search in progress paused: it goes on at the next update. Until a search since the
  /// filter converged has finished, or while this one looks for the next look-alike after one
  /// lost, the estimate is unverified.
  void pauseSearch();
  /// Leaves the rival of `test` out of later searches, and keeps it under watch when the guard
  /// says so (the oldest beyond the guard's memory is forgotten).
  void rememberRejected(RivalTest test);
  /// Moves the rejected places by odometry and, when they are watched, adds this scan's evidence.
  void watchRejected(const mrpt::obs::CObservation2DRangeScan& scan, const SeeThroughPenalty::Scan* see_through,
                     const mrpt::math::TPose2D& mean, const mrpt::poses::CPose2D& increment);
  /// A watched place whose lead for the tracked pose fell to the guard's reopen level, and that
  /// `scan` ranks a look-alike of `mean`, becomes the rival under test again; true when one did.
  bool reopenRejected(const mrpt::obs::CObservation2DRangeScan& scan, const SeeThroughPenalty::Scan* see_through,
                      const mrpt::math::TPose2D& mean);
  /// The guard's share of the particles, spread around `place`; every weight reset.
  void moveShareOfParticlesTo(const mrpt::math::TPose2D& place);
  /// Charges each particle for the scan's beams it would have seen through the map.
  void weighSeeThrough(const SeeThroughPenalty::Scan& see_through);

  std::shared_ptr<mrpt::maps::COccupancyGridMap2D> map_;
  std::shared_ptr<ParticleInitializer> init_;
  MclParams params_;
  mrpt::slam::CMonteCarloLocalization2D pf_;
  mrpt::bayes::CParticleFilter filter_;
  bool initialized_ = false;
  int initializations_ = 0;
  uint64_t resample_draws_ = 0;
  /// The initializer's KLD sizing for this start (none: fixed count), and the start's count,
  /// which caps it.
  std::optional<KldResampling> kld_resampling_;
  std::size_t start_particles_ = 0;
  int concentrated_resamplings_ = 0;  ///< in a row, since this start (KLD sizing waits for them)
  /// Made with the filter when kidnap detection is on, or with a guard that has a fit floor: its
  /// distance field is map preparation, not charged to an update.
  std::unique_ptr<ScanFitScorer> fit_scorer_;
  /// Made with the filter when MclParams::see_through is on; null otherwise.
  std::unique_ptr<SeeThroughPenalty> see_through_;
  KidnapDetector kidnap_;
  std::shared_ptr<const LookAlikeGuard> guard_;
  bool converged_ = false;              ///< the particles were concentrated at the last update
  int updates_since_check_ = 0;         ///< converged updates since the guard last searched
  int searches_this_update_ = 0;        ///< MclEstimate::look_alike_searches, counted as they run
  double search_cpu_this_update_ = 0.0;  ///< MclEstimate::look_alike_search_cpu_s, likewise [s]
  int unfinished_this_update_ = 0;       ///< MclEstimate::look_alike_searches_unfinished, likewise
  /// What the guard's searches since the filter last converged have established.
  enum class ConvergenceCheck {
    none,        ///< no search has finished, none ran out of budget with nothing found
    unfinished,  ///< one ran out of budget with nothing found, or is paused, and none has finished since convergence
    finished,    ///< one finished: the convergence is verified until the filter spreads out
  };
  /// MclEstimate::look_alike_unverified is `unfinished`.
  ConvergenceCheck convergence_check_ = ConvergenceCheck::none;
  /// A look-alike search paused at the guard's max_nodes_per_update, to go on at the next update.
  std::unique_ptr<LookAlikeSearchInProgress> pending_;
  mrpt::poses::CPose2D pending_moved_;  ///< odometry since the pending search's scan
  bool pending_carried_ = false;        ///< it has been carried over to a later update
  bool pending_fresh_ = false;          ///< it started at a fresh convergence
  bool pending_after_loss_ = false;     ///< it started because a look-alike had just lost its test
  std::optional<RivalTest> rival_;      ///< a look-alike being weighed against the mean
  std::deque<RivalTest> rejected_;      ///< look-alikes the scans decided against, moved by odometry
  ScanHistory history_;                 ///< earlier scans a new look-alike is weighed on (guard's history_updates)
  uint64_t guard_draws_ = 0;
  bool unsure_ = false;        ///< at the last update (LaterScanSeedingParams::unsure)
  int later_scans_used_ = 0;   ///< later scans relocalized since the last initialization
  uint64_t later_scan_draws_ = 0;
};

}  // namespace krp
