// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/later_scan_seeding.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <mrpt/math/wrap2pi.h>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

std::size_t particlesNear(const mrpt::slam::CMonteCarloLocalization2D& pf, const mrpt::math::TPose2D& place,
                          const LaterScanSeedingParams& p) {
  std::size_t near = 0;
  for (const auto& particle : pf.m_particles) {
    const auto& d = particle.d;
    if (std::hypot(d.x - place.x, d.y - place.y) <= p.covered_xy_m &&
        std::abs(mrpt::math::wrapToPi(d.phi - place.phi)) <= p.covered_phi_deg * kDegToRad)
      ++near;
  }
  return near;
}

}  // namespace

void validate(const LaterScanSeedingParams& p) {
  if (p.max_scans < 0) throw InputError("later_scans max_scans", "must be >= 0, got " + std::to_string(p.max_scans));
  if (p.max_hypotheses < 1)
    throw InputError("later_scans max_hypotheses", "must be >= 1, got " + std::to_string(p.max_hypotheses));
  if (!(p.share_per_hypothesis > 0.0 && p.share_per_hypothesis * p.max_hypotheses <= 1.0))
    throw InputError("later_scans share_per_hypothesis",
                     "must be in (0, 1 / max_hypotheses], got " + std::to_string(p.share_per_hypothesis));
  if (!(p.covered_xy_m >= 0.0 && p.covered_phi_deg >= 0.0 && p.spread_xy_m >= 0.0 && p.spread_phi_deg >= 0.0))
    throw InputError("later_scans", "covered_* and spread_* must be >= 0");
}

int seedFromLaterScan(mrpt::slam::CMonteCarloLocalization2D& pf, const Ranking& ranking,
                      const mrpt::poses::CPose2D& motion, const LaterScanSeedingParams& p, Rng& rng) {
  const std::size_t n = pf.m_particles.size();
  const std::size_t every = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(1.0 / p.share_per_hypothesis)));
  const std::size_t share = n / every;
  if (share == 0) return 0;
  const mrpt::poses::CPose2D back = -motion;
  int seeded = 0;
  const std::size_t considered = std::min({ranking.hypotheses.size(), static_cast<std::size_t>(p.max_hypotheses), every});
  for (std::size_t j = 0; j < considered; ++j) {
    const auto& h = ranking.hypotheses[j];
    if (2 * particlesNear(pf, h.pose, p) >= share) continue;
    for (std::size_t i = static_cast<std::size_t>(seeded); i < n; i += every) {
      const mrpt::math::TPose2D drawn(rng.normal(h.pose.x, p.spread_xy_m), rng.normal(h.pose.y, p.spread_xy_m),
                                      rng.normal(h.pose.phi, p.spread_phi_deg * kDegToRad));
      auto& d = pf.m_particles[i].d;
      d = (mrpt::poses::CPose2D(drawn) + back).asTPose();
      d.normalizePhi();
    }
    ++seeded;
  }
  if (seeded > 0)
    for (auto& particle : pf.m_particles) particle.log_w = 0.0;
  return seeded;
}

}  // namespace krp
