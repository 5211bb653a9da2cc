// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/seeded_initializer.h"

#include <algorithm>
#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/common/thread_cpu_time.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

double clampedStd(double variance, double lo, double hi) { return std::clamp(std::sqrt(std::max(variance, 0.0)), lo, hi); }

std::vector<cv::Point> freeCells(const mrpt::maps::COccupancyGridMap2D& map, double min_freeness) {
  CellClassParams p;
  p.max_free_occupancy = 1.0 - min_freeness;
  return maskedCells(freeMask(map, p));
}

}  // namespace

SeededInitializer::SeededInitializer(HypothesisSource source, SeededInitParams params, std::string name)
    : source_(std::move(source)), params_(params), name_(std::move(name)) {
  if (!(params_.uniform_fraction >= 0.0 && params_.uniform_fraction < 1.0))
    throw InputError("seeded uniform_fraction", "must be in [0, 1), got " + std::to_string(params_.uniform_fraction));
  if (params_.min_particles > params_.max_particles)
    throw InputError("seeded min_particles", "exceeds max_particles");
}

std::optional<KldSampleSizeParams> SeededInitializer::kldResampling() const {
  if (last_ && last_->fell_back_to_uniform && params_.fallback_shrinks.enabled) return params_.fallback_shrinks;
  return std::nullopt;
}

void SeededInitializer::initialize(mrpt::slam::CMonteCarloLocalization2D& pf,
                                   mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf_options,
                                   const mrpt::maps::COccupancyGridMap2D& map, const mrpt::obs::CSensoryFrame& first) {
  const double start_s = threadCpuSeconds();
  SeedingRecord rec;
  const auto scan = first.getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
  if (!scan) throw InputError("first observation", "holds no 2D range scan to relocalize from");
  rec.ranking = source_(*scan);
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

  const auto seeded_target = params_.particles_per_hypothesis * hyps.size();
  const auto total = std::clamp(
      static_cast<std::size_t>(std::ceil(static_cast<double>(seeded_target) / (1.0 - params_.uniform_fraction))),
      params_.min_particles, params_.max_particles);
  const auto cells = freeCells(map, params_.free_cell_min_freeness);
  rec.uniform_particles = cells.empty() ? 0 : static_cast<std::size_t>(std::lround(params_.uniform_fraction * total));
  const std::size_t seeded = total - rec.uniform_particles;

  double confidence_sum = 0;
  for (const auto& h : hyps) confidence_sum += h.confidence;
  Rng rng(params_.seed);
  pf.m_particles.clear();
  pf.m_particles.resize(total);
  std::size_t next = 0;
  for (size_t i = 0; i < hyps.size() && next < seeded; ++i) {
    const auto& h = hyps[i];
    // Equal shares when every confidence is zero: the hypotheses are all we have.
    const double share = confidence_sum > 0 ? h.confidence / confidence_sum : 1.0 / hyps.size();
    const bool last = i + 1 == hyps.size();
    const std::size_t n = last ? seeded - next : std::min(seeded - next, static_cast<std::size_t>(std::lround(share * seeded)));
    const double sx = clampedStd(h.cov(0, 0), params_.min_std_xy_m, params_.max_std_xy_m);
    const double sy = clampedStd(h.cov(1, 1), params_.min_std_xy_m, params_.max_std_xy_m);
    const double sphi = clampedStd(h.cov(2, 2), params_.min_std_yaw_deg * kDegToRad, params_.max_std_yaw_deg * kDegToRad);
    for (std::size_t k = 0; k < n; ++k, ++next)
      pf.m_particles[next].d = {rng.normal(h.pose.x, sx), rng.normal(h.pose.y, sy), rng.normal(h.pose.phi, sphi)};
  }
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
