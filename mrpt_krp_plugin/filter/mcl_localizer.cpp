// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/mcl_localizer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/common/thread_cpu_time.h"

namespace krp {

namespace {

/// The later-scan seeding's own random stream: turning it on moves no other component's draws.
constexpr uint64_t kLaterScanStream = 0x5851f42d4c957f2dull;

/// The robot's motion since the last update, as the action records it (zero when it does not).
mrpt::poses::CPose2D odometryIncrement(const mrpt::obs::CActionCollection& action) {
  const auto move = action.getBestMovementEstimation();
  if (!move || !move->poseChange) return {};
  return move->poseChange->getMeanVal();
}

// The filter needs its own copy of the map: MRPT keeps the likelihood cache inside it.
std::shared_ptr<mrpt::maps::COccupancyGridMap2D> filledCopy(const mrpt::maps::COccupancyGridMap2D& map,
                                                            const SensorModelParams& sensor) {
  auto own = std::make_shared<mrpt::maps::COccupancyGridMap2D>(map);
  fillLikelihoodField(*own, sensor);
  return own;
}

// A prepared map's cache is copied filled; it must hold the filter's own model's likelihoods.
std::shared_ptr<mrpt::maps::COccupancyGridMap2D> checkedCopy(const SensorModelMap& map, const SensorModelParams& sensor) {
  if (map.sensor != sensor)
    throw std::invalid_argument("MclLocalizer: the map was prepared for another sensor model than the filter's");
  return std::make_shared<mrpt::maps::COccupancyGridMap2D>(*map.grid);
}

}  // namespace

MclLocalizer::MclLocalizer(std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map,
                           std::shared_ptr<ParticleInitializer> init, MclParams params)
    : MclLocalizer(OwnMap{filledCopy(*map, params.sensor)}, std::move(init), params) {}

MclLocalizer::MclLocalizer(const SensorModelMap& map, std::shared_ptr<ParticleInitializer> init, MclParams params)
    : MclLocalizer(OwnMap{checkedCopy(map, params.sensor)}, std::move(init), params) {}

MclLocalizer::MclLocalizer(OwnMap map, std::shared_ptr<ParticleInitializer> init, MclParams params)
    : map_(std::move(map.grid)), init_(std::move(init)), params_(params), kidnap_(params.kidnap) {
  pf_.options.metricMap = map_;
  auto& o = filter_.m_options;
  o.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
  o.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
  o.BETA = 0.0;  // never resample inside executeOn: see the class comment
  if (params_.kidnap.enabled) fit_scorer_ = std::make_unique<ScanFitScorer>(*map_);
  if (params_.see_through.enabled)
    see_through_ = std::make_unique<SeeThroughPenalty>(*map_, params_.sensor, params_.see_through);
  validate(params_.later_scans);
}

void MclLocalizer::setLookAlikeGuard(std::shared_ptr<const LookAlikeGuard> guard) {
  guard_ = std::move(guard);
  history_ = ScanHistory(guard_ ? static_cast<std::size_t>(guard_->params().history_updates) : 0);
  if (guard_ && guard_->params().min_fit_fraction > 0.0 && !fit_scorer_)
    fit_scorer_ = std::make_unique<ScanFitScorer>(*map_);
}

void MclLocalizer::resampleSystematicIfNeeded() {
  const size_t n = pf_.m_particles.size();
  if (n == 0) return;
  const double ess = pf_.ESS();
  if (ess >= params_.resample_below_ess) return;
  double max_lw = -std::numeric_limits<double>::infinity();
  for (const auto& p : pf_.m_particles) max_lw = std::max(max_lw, p.log_w);
  std::vector<double> cumulative(n);
  double total = 0.0;
  for (size_t i = 0; i < n; ++i) cumulative[i] = (total += std::exp(pf_.m_particles[i].log_w - max_lw));
  Rng rng(deriveSeed(params_.seed, ++resample_draws_));
  // KLD sizing draws up to the start's count and keeps the prefix it needs; a set that has
  // spread out again regains the start's count.
  const size_t draws = kld_resampling_ ? start_particles_ : n;
  const bool concentrated =
      kld_resampling_ &&
      isConcentrated(filterSpread(std::get<0>(pf_.getCovarianceAndMean())), kld_resampling_->params.only_once_concentrated);
  concentrated_resamplings_ = concentrated ? concentrated_resamplings_ + 1 : 0;
  const bool size_by_kld = concentrated && concentrated_resamplings_ >= kld_resampling_->params.concentrated_resamplings;
  const double step = total / static_cast<double>(draws);
  double u = rng.uniform(0.0, step);
  std::vector<mrpt::math::TPose2D> picked(draws);
  size_t j = 0;
  for (size_t i = 0; i < draws; ++i, u += step) {
    while (j + 1 < n && cumulative[j] < u) ++j;
    picked[i] = pf_.m_particles[j].d;
  }
  size_t kept = draws;
  if (size_by_kld) {
    // Systematic draws come in the order of the old set: shuffled, any prefix is a fair sample.
    rng.shuffle(picked);
    kept = kldSampleCount(picked, kld_resampling_->params.size, kld_resampling_->min_particles);
  }
  pf_.m_particles.resize(kept);
  for (size_t i = 0; i < kept; ++i) {
    pf_.m_particles[i].d = picked[i];
    pf_.m_particles[i].log_w = 0.0;
  }
}

void MclLocalizer::weighSeeThrough(const SeeThroughPenalty::Scan& see_through) {
  for (auto& p : pf_.m_particles) p.log_w -= see_through.nats(p.d);
}

void MclLocalizer::moveShareOfParticlesTo(const mrpt::math::TPose2D& place) {
  const auto& gp = guard_->params();
  // Every k-th particle moves, so the share is exact and the rest keep their spread.
  const size_t every = std::max<size_t>(1, static_cast<size_t>(std::lround(1.0 / gp.moved_share)));
  Rng rng(deriveSeed(params_.seed ^ 0x9e3779b97f4a7c15ull, ++guard_draws_));
  const double spread_rad = gp.spread_deg * M_PI / 180.0;
  for (size_t i = 0; i < pf_.m_particles.size(); ++i) {
    auto& p = pf_.m_particles[i];
    p.log_w = 0.0;  // both places start even: the next scans decide
    if (i % every != 0) continue;
    p.d = mrpt::math::TPose2D(rng.normal(place.x, gp.spread_m), rng.normal(place.y, gp.spread_m),
                              mrpt::math::wrapToPi(rng.normal(place.phi, spread_rad)));
  }
}

void MclLocalizer::rememberRejected(RivalTest test) {
  test.holdLeadAt(guard_->params().rival_test.decisive_log_ratio);
  rejected_.push_back(std::move(test));
  while (rejected_.size() > static_cast<size_t>(guard_->params().remembered_rejected)) rejected_.pop_front();
}

void MclLocalizer::watchRejected(const mrpt::obs::CObservation2DRangeScan& scan,
                                 const SeeThroughPenalty::Scan* see_through, const mrpt::math::TPose2D& mean,
                                 const mrpt::poses::CPose2D& increment) {
  const auto& gp = guard_->params();
  for (auto& test : rejected_) test.move(increment);
  if (!gp.watch_rejected) return;
  for (auto& test : rejected_) {
    test.update(*map_, scan, mean, see_through);
    test.holdLeadAt(gp.rival_test.decisive_log_ratio);
  }
  // Re-fitted scan after scan, a watched place along a corridor can slide onto the mean.
  rejected_.erase(std::remove_if(rejected_.begin(), rejected_.end(),
                                 [&](const RivalTest& t) { return guard_->samePlace(t.rival(), mean); }),
                  rejected_.end());
}

bool MclLocalizer::reopenRejected(const mrpt::obs::CObservation2DRangeScan& scan,
                                  const SeeThroughPenalty::Scan* see_through, const mrpt::math::TPose2D& mean) {
  const auto& gp = guard_->params();
  if (!gp.watch_rejected) return false;
  const auto reopened = std::find_if(rejected_.begin(), rejected_.end(), [&](const RivalTest& t) {
    return t.logRatio() <= gp.reopen_log_ratio && guard_->isLookAlike(scan, t.rival(), mean, see_through);
  });
  if (reopened == rejected_.end()) return false;
  rival_ = *reopened;
  rejected_.erase(reopened);
  return true;
}

bool MclLocalizer::guardConvergence(const mrpt::obs::CObservation2DRangeScan& scan,
                                    const SeeThroughPenalty::Scan* see_through, const mrpt::math::TPose2D& mean,
                                    const mrpt::math::CMatrixDouble33& cov, const mrpt::poses::CPose2D& increment) {
  const auto& gp = guard_->params();
  if (!isConcentrated(filterSpread(cov), gp.converged)) {
    // A spread-out filter says for itself that it is not settled; the next convergence starts afresh.
    converged_ = false;
    rival_.reset();
    rejected_.clear();
    pending_.reset();
    convergence_check_ = ConvergenceCheck::none;
    return false;
  }
  const bool fresh = !converged_;
  converged_ = true;
  if (pending_) {
    // Its place is for the scan it started on: a twin robot there has moved as this one has.
    pending_moved_ = pending_moved_ + increment;
    pending_carried_ = true;
  }
  watchRejected(scan, see_through, mean, increment);
  // Reopened on this scan's evidence, already counted: the estimate is ambiguous from now.
  if (!rival_ && reopenRejected(scan, see_through, mean)) {
    pending_.reset();  // the reopened place is weighed first; a later search starts afresh
    return false;
  }
  if (rival_) {
    rival_->move(increment);
    const auto verdict = rival_->update(*map_, scan, mean, see_through);
    const auto place = rival_->rival();
    // Re-fitted scan after scan, a rival along a corridor can slide onto the mean: then it is
    // the same place, no longer an alternative, and a fresh search follows.
    if (guard_->samePlace(place, mean)) {
      rival_.reset();
    } else {
      if (verdict == RivalTest::Verdict::undecided) return false;
      if (verdict == RivalTest::Verdict::rival_wins) {
        rival_.reset();
        updates_since_check_ = 0;
        moveShareOfParticlesTo(place);
        return true;
      }
      rememberRejected(*rival_);
      rival_.reset();
      updates_since_check_ = 0;
      // In a corridor many places tie: the one that lost may not be the last look-alike. It
      // counts as one of the look-alikes weighed in this update.
      return gp.searches_per_update > 1 &&
             searchForLookAlike(scan, see_through, mean, increment, fresh, gp.searches_per_update - 1, true);
    }
  }
  ++updates_since_check_;
  const bool due = pending_ || fresh ||
                   (gp.recheck_every_updates > 0 && updates_since_check_ >= gp.recheck_every_updates);
  if (!due) return false;
  return searchForLookAlike(scan, see_through, mean, increment, fresh, gp.searches_per_update, false);
}

void MclLocalizer::pauseSearch() {
  // A search that follows a look-alike which just lost is looking for the next one: until it
  // ends, nothing says none is left (a whole search would have answered in this update).
  if (pending_after_loss_ || convergence_check_ != ConvergenceCheck::finished)
    convergence_check_ = ConvergenceCheck::unfinished;
}

bool MclLocalizer::searchForLookAlike(const mrpt::obs::CObservation2DRangeScan& scan,
                                      const SeeThroughPenalty::Scan* see_through, const mrpt::math::TPose2D& mean,
                                      const mrpt::poses::CPose2D& increment, bool fresh, int searches,
                                      bool after_loss) {
  const auto& gp = guard_->params();
  updates_since_check_ = 0;
  const long long per_update = gp.max_nodes_per_update;  // 0: no limit
  long long nodes_left = per_update;
  // A look-alike that loses at once is excluded and the search repeated, so that an estimate
  // reported unambiguous has no look-alike left, not merely one that just lost.
  for (int search = 0; search < searches; ++search) {
    const double t0 = threadCpuSeconds();
    if (!pending_) {
      std::vector<mrpt::math::TPoint2D> excluded;
      for (const auto& test : rejected_) excluded.emplace_back(test.rival().x, test.rival().y);
      pending_ = guard_->startSearch(scan, mean, excluded, see_through);
      pending_moved_ = mrpt::poses::CPose2D();
      pending_carried_ = false;
      pending_fresh_ = fresh;
      pending_after_loss_ = after_loss || search > 0;
    }
    if (per_update > 0 && nodes_left <= 0) {
      search_cpu_this_update_ += threadCpuSeconds() - t0;
      pauseSearch();
      return false;
    }
    const long long nodes_before = pending_->nodesScored();
    const auto result = guard_->resume(*pending_, per_update > 0 ? nodes_left : 0);
    nodes_left -= pending_->nodesScored() - nodes_before;
    search_cpu_this_update_ += threadCpuSeconds() - t0;
    ++searches_this_update_;
    if (result.paused) {
      pauseSearch();
      return false;
    }
    const bool carried = pending_carried_, started_fresh = pending_fresh_;
    const auto moved = pending_moved_;
    pending_.reset();
    if (!result.cut_short)
      convergence_check_ = ConvergenceCheck::finished;
    else if (!result.found && convergence_check_ != ConvergenceCheck::finished)
      convergence_check_ = ConvergenceCheck::unfinished;
    if (!result.found) {
      if (result.cut_short) ++unfinished_this_update_;
      return false;
    }
    auto found = *result.found;
    if (carried) {
      // Found for an earlier scan: moved along the odometry since, and weighed on this one.
      found.pose = (mrpt::poses::CPose2D(found.pose) + moved).asTPose();
      if (guard_->samePlace(found.pose, mean)) continue;  // it slid onto the mean: no alternative
      found.score = guard_->score(scan, found.pose, see_through);
      found.tracked_score = guard_->score(scan, mean, see_through);
    }
    // A place that fits at least as well at a fresh convergence gets particles at once. Later,
    // and for places that fit a little worse, the scans that follow decide first: moving
    // particles at every check would keep a filter that is right from ever settling.
    if (started_fresh && guard_->fitsAtLeastAsWell(found)) {
      moveShareOfParticlesTo(found.pose);
      return true;
    }
    rival_.emplace(history_.primedTest(found.pose, mean, increment, *map_, gp.rival_test));
    if (rival_->update(*map_, scan, mean, see_through) != RivalTest::Verdict::tracked_wins) return false;
    rememberRejected(*rival_);
    rival_.reset();
  }
  return false;
}

MclEstimate MclLocalizer::update(const RawlogStep& step) {
  const double t0 = threadCpuSeconds();
  MclEstimate e;
  searches_this_update_ = 0;
  search_cpu_this_update_ = 0.0;
  unfinished_this_update_ = 0;
  const auto& later = params_.later_scans;
  if (initialized_ && later.enabled && unsure_ && later_scans_used_ < later.max_scans) {
    if (const auto ranking = init_->laterHypotheses(*step.observations)) {
      ++later_scans_used_;
      e.later_scan_relocalized = true;
      Rng rng(deriveSeed(params_.seed ^ kLaterScanStream, ++later_scan_draws_));
      const auto motion = step.action ? odometryIncrement(*step.action) : mrpt::poses::CPose2D();
      e.later_scan_hypotheses_seeded = seedFromLaterScan(pf_, *ranking, motion, later, rng);
    }
  }
  if (!initialized_) {
    reseedMrptGlobalRandom(params_.seed + static_cast<uint32_t>(initializations_));
    init_->initialize(pf_, filter_.m_options, *map_, *step.observations);
    kld_resampling_ = init_->kldResampling();
    start_particles_ = pf_.size();
    concentrated_resamplings_ = 0;
    initialized_ = true;
    ++initializations_;
    e.initialized = true;
    kidnap_.reset();
    converged_ = false;
    convergence_check_ = ConvergenceCheck::none;
    rival_.reset();
    rejected_.clear();
    pending_.reset();
    history_.clear();  // scans from before a re-seed may be from before a kidnap
    later_scans_used_ = 0;
  }
  auto action = step.action;
  if (!action) {
    // No odometry recorded for this step: a zero motion with the model's minimum noise.
    action = mrpt::obs::CActionCollection::Create();
    mrpt::obs::CActionRobotMovement2D move;
    move.computeFromOdometry(mrpt::poses::CPose2D(0, 0, 0), OdometryModelParams{}.toMrpt());
    action->insert(move);
  }
  mrpt::bayes::CParticleFilter::TParticleFilterStats stats;
  filter_.executeOn(pf_, action.get(), step.observations.get(), &stats);
  const auto scan = step.observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
  // Read once: every particle and every place the guard weighs are charged on this scan.
  std::optional<SeeThroughPenalty::Scan> see_through;
  if (see_through_ && scan) {
    see_through = see_through_->forScan(*scan);
    weighSeeThrough(*see_through);
  }
  const size_t weighed = pf_.size();
  if (!filter_.m_options.adaptiveSampleSize) resampleSystematicIfNeeded();

  auto [cov, mean] = pf_.getCovarianceAndMean();
  const auto increment = odometryIncrement(*action);
  if (guard_ && scan &&
      guardConvergence(*scan, see_through ? &*see_through : nullptr, mean.asTPose(), cov, increment)) {
    e.look_alike_found = true;
    std::tie(cov, mean) = pf_.getCovarianceAndMean();
  }
  if (guard_ && scan) history_.push(*scan, see_through, increment);
  e.mean = mean.asTPose();
  e.cov = cov;
  if (rival_) {
    e.ambiguous_with = rival_->rival();
    e.cov = covarianceWithLookAlike(cov, e.mean, rival_->rival());
  }
  if (guard_ && converged_ && convergence_check_ == ConvergenceCheck::unfinished) {
    e.look_alike_unverified = true;
    const auto& gp = guard_->params();
    if (gp.unverified_is_unsettled)
      e.cov = covarianceWithSpreadAtLeast(e.cov, gp.unexplained_xy_std_m, gp.unexplained_phi_std_deg);
  }
  const bool fit_floor = guard_ && guard_->params().min_fit_fraction > 0.0 && converged_;
  if (scan && (params_.kidnap.enabled || fit_floor)) e.fit_fraction = fit_scorer_->score(*scan, e.mean).fit_fraction;
  if (fit_floor && e.fit_fraction >= 0.0 && e.fit_fraction < guard_->params().min_fit_fraction) {
    const auto& gp = guard_->params();
    e.scan_unexplained = true;
    e.cov = covarianceWithSpreadAtLeast(e.cov, gp.unexplained_xy_std_m, gp.unexplained_phi_std_deg);
  }
  if (params_.kidnap.enabled && e.fit_fraction >= 0.0) {
    e.kidnap_detected = kidnap_.update(e.fit_fraction);
    if (e.kidnap_detected) initialized_ = false;
  }
  e.particles = weighed;
  unsure_ = !isConcentrated(filterSpread(cov), later.unsure) || e.scan_unexplained;
  e.look_alike_searches = searches_this_update_;
  e.look_alike_search_cpu_s = search_cpu_this_update_;
  e.look_alike_searches_unfinished = unfinished_this_update_;
  e.look_alike_search_pending = pending_ != nullptr;
  e.cpu_s = threadCpuSeconds() - t0;
  return e;
}

}  // namespace krp
