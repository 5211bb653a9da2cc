// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/mcl_localizer.h"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "mrpt_krp_plugin/common/random.h"

namespace krp {

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

MclLocalizer::MclLocalizer(std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map,
                           std::shared_ptr<ParticleInitializer> init, MclParams params)
    // The filter needs its own copy: MRPT caches the likelihood field inside the map.
    : map_(std::make_shared<mrpt::maps::COccupancyGridMap2D>(*map)), init_(std::move(init)), params_(params),
      kidnap_(params.kidnap) {
  auto& lo = map_->likelihoodOptions;
  lo.likelihoodMethod = mrpt::maps::COccupancyGridMap2D::lmLikelihoodField_Thrun;
  lo.LF_decimation = static_cast<uint32_t>(params_.sensor.decimation);
  lo.LF_stdHit = static_cast<float>(params_.sensor.std_hit_m);
  lo.LF_maxCorrsDistance = static_cast<float>(params_.sensor.max_corr_distance_m);
  lo.LF_zHit = static_cast<float>(params_.sensor.z_hit);
  lo.LF_zRandom = static_cast<float>(params_.sensor.z_random);
  lo.LF_useSquareDist = false;
  lo.enableLikelihoodCache = true;
  pf_.options.metricMap = map_;
  auto& o = filter_.m_options;
  o.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
  o.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
  o.BETA = 0.0;  // never resample inside executeOn: see the class comment
  if (params_.kidnap.enabled) fit_scorer_ = std::make_unique<ScanFitScorer>(*map_);
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
  const double step = total / static_cast<double>(n);
  double u = rng.uniform(0.0, step);
  auto old = pf_.m_particles;
  size_t j = 0;
  for (size_t i = 0; i < n; ++i, u += step) {
    while (j + 1 < n && cumulative[j] < u) ++j;
    pf_.m_particles[i].d = old[j].d;
    pf_.m_particles[i].log_w = 0.0;
  }
}

bool MclLocalizer::guardConvergence(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& mean,
                                    const mrpt::math::CMatrixDouble33& cov) {
  const auto& gp = guard_->params();
  const bool converged = std::max(std::sqrt(cov(0, 0)), std::sqrt(cov(1, 1))) < gp.converged_std_m &&
                         std::sqrt(cov(2, 2)) * 180.0 / M_PI < gp.converged_std_deg;
  if (!converged) {
    convergence_checked_ = false;  // the next convergence is checked again
    return false;
  }
  if (convergence_checked_) return false;
  convergence_checked_ = true;
  const auto other = guard_->lookAlike(scan, mean);
  if (!other) return false;
  // Every k-th particle moves, so the share is exact and the rest keep their spread.
  const size_t every = std::max<size_t>(1, static_cast<size_t>(std::lround(1.0 / gp.moved_share)));
  Rng rng(deriveSeed(params_.seed ^ 0x9e3779b97f4a7c15ull, ++guard_draws_));
  const double spread_rad = gp.spread_deg * M_PI / 180.0;
  for (size_t i = 0; i < pf_.m_particles.size(); ++i) {
    auto& p = pf_.m_particles[i];
    p.log_w = 0.0;  // both places start even: the next scans decide
    if (i % every != 0) continue;
    p.d = mrpt::math::TPose2D(rng.normal(other->x, gp.spread_m), rng.normal(other->y, gp.spread_m),
                              mrpt::math::wrapToPi(rng.normal(other->phi, spread_rad)));
  }
  return true;
}

MclEstimate MclLocalizer::update(const RawlogStep& step) {
  const double t0 = threadCpuSeconds();
  MclEstimate e;
  if (!initialized_) {
    reseedMrptGlobalRandom(params_.seed + static_cast<uint32_t>(initializations_));
    init_->initialize(pf_, filter_.m_options, *map_, *step.observations);
    initialized_ = true;
    ++initializations_;
    e.initialized = true;
    kidnap_.reset();
    convergence_checked_ = false;
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
  if (!filter_.m_options.adaptiveSampleSize) resampleSystematicIfNeeded();

  auto [cov, mean] = pf_.getCovarianceAndMean();
  const auto scan = step.observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
  if (guard_ && scan && guardConvergence(*scan, mean.asTPose(), cov)) {
    e.look_alike_found = true;
    std::tie(cov, mean) = pf_.getCovarianceAndMean();
  }
  e.cov = cov;
  e.mean = mean.asTPose();
  if (fit_scorer_ && scan) {
    e.fit_fraction = fit_scorer_->score(*scan, e.mean).fit_fraction;
    e.kidnap_detected = kidnap_.update(e.fit_fraction);
    if (e.kidnap_detected) initialized_ = false;
  }
  e.particles = pf_.size();
  e.cpu_s = threadCpuSeconds() - t0;
  return e;
}

}  // namespace krp
