// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/seeded_initializer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/common/thread_cpu_time.h"
#include "mrpt_krp_plugin/filter/free_cells.h"
#include "mrpt_krp_plugin/filter/kld_sample_size.h"

namespace krp {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

double clampedStd(double variance, double lo, double hi) { return std::clamp(std::sqrt(std::max(variance, 0.0)), lo, hi); }

/// One hypothesis's Gaussian in the prior, and its share of the seeded particles.
struct Cloud {
  mrpt::math::TPose2D mean;
  double share = 0, std_x = 0, std_y = 0, std_phi = 0;
  mrpt::math::TPose2D draw(Rng& rng) const {
    return {rng.normal(mean.x, std_x), rng.normal(mean.y, std_y), rng.normal(mean.phi, std_phi)};
  }
};

/// `count` draws split between the clouds by share, cloud after cloud (the fixed-count rule).
std::vector<mrpt::math::TPose2D> drawsPerCloud(const std::vector<Cloud>& clouds, std::size_t count, Rng& rng) {
  std::vector<mrpt::math::TPose2D> out;
  out.reserve(count);
  for (std::size_t i = 0; i < clouds.size() && out.size() < count; ++i) {
    const std::size_t left = count - out.size();
    const std::size_t n = i + 1 == clouds.size() ? left
                                                 : std::min(left, static_cast<std::size_t>(std::lround(clouds[i].share * count)));
    for (std::size_t k = 0; k < n; ++k) out.push_back(clouds[i].draw(rng));
  }
  return out;
}

/// `count` draws from the mixture, each from a cloud picked by its share, so that any prefix is
/// a fair sample of the whole prior (which KLD sampling's prefix rule needs).
std::vector<mrpt::math::TPose2D> mixtureDraws(const std::vector<Cloud>& clouds, std::size_t count, Rng& rng) {
  std::vector<mrpt::math::TPose2D> out(count);
  for (auto& pose : out) {
    double u = rng.uniform(0.0, 1.0);
    std::size_t i = 0;
    while (i + 1 < clouds.size() && u >= clouds[i].share) u -= clouds[i++].share;
    pose = clouds[i].draw(rng);
  }
  return out;
}

}  // namespace

SeededInitializer::SeededInitializer(HypothesisSource source, SeededInitParams params, std::string name)
    : SeededInitializer(
          TimedHypothesisSource([source = std::move(source)](const mrpt::obs::CObservation2DRangeScan& scan) {
            return TimedRanking{source(scan), std::nullopt};
          }),
          params, std::move(name)) {}

SeededInitializer::SeededInitializer(TimedHypothesisSource source, SeededInitParams params, std::string name)
    : source_(std::move(source)), params_(params), name_(std::move(name)) {
  if (!(params_.uniform_fraction >= 0.0 && params_.uniform_fraction < 1.0))
    throw InputError("seeded uniform_fraction", "must be in [0, 1), got " + std::to_string(params_.uniform_fraction));
  if (params_.min_particles > params_.max_particles)
    throw InputError("seeded min_particles", "exceeds max_particles");
}

std::optional<KldResampling> SeededInitializer::kldResampling() const {
  if (last_ && last_->fell_back_to_uniform && params_.fallback_shrinks)
    return KldResampling{*params_.fallback_shrinks, params_.min_particles};
  return std::nullopt;
}

std::optional<Ranking> SeededInitializer::laterHypotheses(const mrpt::obs::CSensoryFrame& frame) {
  const auto scan = frame.getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
  if (!scan) return std::nullopt;
  return source_(*scan).ranking;
}

void SeededInitializer::initialize(mrpt::slam::CMonteCarloLocalization2D& pf,
                                   mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf_options,
                                   const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CSensoryFrame& first) {
  const double start_s = threadCpuSeconds();
  SeedingRecord rec;
  const auto scan = first.getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
  if (!scan) throw InputError("first observation", "holds no 2D range scan to relocalize from");
  auto answer = source_(*scan);
  rec.ranking = std::move(answer.ranking);
  rec.stage_times = answer.stage_times;
  const auto& hyps = rec.ranking.hypotheses;
  pf_options.adaptiveSampleSize = false;
  if (hyps.empty()) {
    UniformInitializer uniform(params_.fallback);
    uniform.initialize(pf, pf_options, map, first);
    rec.particles = rec.uniform_particles = pf.size();
    rec.fell_back_to_uniform = true;
    rec.cpu_s = threadCpuSeconds() - start_s;
    last_ = rec;
    return;
  }

  // Each hypothesis's cloud: its alignment covariance, clamped to a concentrated yet trackable spread.
  std::vector<Cloud> clouds;
  double confidence_sum = 0;
  for (const auto& h : hyps) confidence_sum += h.confidence;
  for (const auto& h : hyps) {
    // Equal shares when every confidence is zero: the hypotheses are all we have.
    const double share = confidence_sum > 0 ? h.confidence / confidence_sum : 1.0 / hyps.size();
    clouds.push_back({h.pose, share, clampedStd(h.cov(0, 0), params_.min_std_xy_m, params_.max_std_xy_m),
                      clampedStd(h.cov(1, 1), params_.min_std_xy_m, params_.max_std_xy_m),
                      clampedStd(h.cov(2, 2), params_.min_std_yaw_deg * kDegToRad, params_.max_std_yaw_deg * kDegToRad)});
  }
  std::vector<cv::Point> found;  // only when no FreeCells of this map were given
  const bool given = free_cells_ && free_cells_->describes(map, params_.free_cell_min_freeness);
  if (!given) found = freeCellsOf(map, params_.free_cell_min_freeness);
  const std::vector<cv::Point>& cells = given ? free_cells_->cells() : found;
  // The total counts the uniform share the map asks for; with no free cell it goes to the clouds.
  const auto uniform_count = [&](std::size_t total) {
    return cells.empty() ? std::size_t{0} : static_cast<std::size_t>(std::lround(params_.uniform_fraction * total));
  };
  const auto total_for = [&](std::size_t seeded) {
    return std::clamp(static_cast<std::size_t>(std::ceil(static_cast<double>(seeded) / (1.0 - params_.uniform_fraction))),
                      params_.min_particles, params_.max_particles);
  };
  Rng rng(params_.seed);
  std::vector<mrpt::math::TPose2D> seeded;
  std::size_t total = 0;
  if (params_.count_from_spread) {
    // Draws up to the cap, in random order, then keeps the prefix that KLD sampling asks for.
    // Its floor is min_particles' seeded part: the bound for the one bin a first draw occupies is
    // zero, so without a floor the rule would stop there, as KLD sampling never starts that small.
    const std::size_t cap = params_.max_particles - uniform_count(params_.max_particles);
    seeded = mixtureDraws(clouds, cap, rng);
    const std::size_t floor = params_.min_particles - uniform_count(params_.min_particles);
    total = total_for(kldSampleCount(seeded, *params_.count_from_spread, floor));
    seeded.resize(std::min(cap, total - uniform_count(total)));
  } else {
    total = total_for(params_.particles_per_hypothesis * hyps.size());
    seeded = drawsPerCloud(clouds, total - uniform_count(total), rng);
  }
  rec.uniform_particles = total - seeded.size();
  pf.m_particles.clear();
  pf.m_particles.resize(total);
  std::size_t next = 0;
  for (; next < seeded.size(); ++next) pf.m_particles[next].d = seeded[next];
  for (; next < total; ++next) {
    const auto& cell = cells[static_cast<size_t>(rng.uniformInt(0, static_cast<int>(cells.size()) - 1))];
    const double half = 0.5 * map.getResolution();
    pf.m_particles[next].d = {map.idx2x(cell.x) + rng.uniform(-half, half), map.idx2y(cell.y) + rng.uniform(-half, half),
                              rng.uniform(-M_PI, M_PI)};
  }
  for (auto& p : pf.m_particles) {
    p.d.normalizePhi();
    p.log_w = 0.0;
  }
  rec.particles = total;
  rec.cpu_s = threadCpuSeconds() - start_s;
  last_ = rec;
}

}  // namespace krp
