// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/kld_sample_size.h"

#include <cmath>
#include <cstdint>
#include <unordered_set>

#include <mrpt/math/wrap2pi.h>

namespace krp {

namespace {

// A bin's three indices packed into one key; 21 bits each hold +-1e6 bins, far beyond any map.
uint64_t binKey(const mrpt::math::TPose2D& p, double bin_xy, double bin_phi) {
  constexpr int64_t kOffset = 1 << 20;
  constexpr uint64_t kMask = (uint64_t{1} << 21) - 1;
  const auto index = [&](double v, double bin) {
    return static_cast<uint64_t>(static_cast<int64_t>(std::floor(v / bin)) + kOffset) & kMask;
  };
  return index(p.x, bin_xy) | index(p.y, bin_xy) << 21 | index(mrpt::math::wrapTo2Pi(p.phi), bin_phi) << 42;
}

}  // namespace

std::size_t kldBound(std::size_t occupied_bins, double epsilon, double z) {
  if (occupied_bins <= 1) return 0;
  // Wilson-Hilferty's approximation of the chi-square quantile, as in Fox's paper and amcl.
  const double k = static_cast<double>(occupied_bins - 1);
  const double a = 2.0 / (9.0 * k);
  const double b = 1.0 - a + std::sqrt(a) * z;
  return static_cast<std::size_t>(std::ceil(k / (2.0 * epsilon) * b * b * b));
}

std::size_t kldSampleCount(const std::vector<mrpt::math::TPose2D>& draws, const KldSampleSizeParams& params,
                           std::size_t min_particles) {
  const double bin_phi = params.bin_phi_deg * M_PI / 180.0;
  std::unordered_set<uint64_t> bins;
  for (std::size_t n = 0; n < draws.size(); ++n) {
    bins.insert(binKey(draws[n], params.bin_xy_m, bin_phi));
    const std::size_t kept = n + 1;
    if (kept >= min_particles && kept >= kldBound(bins.size(), params.epsilon, params.z)) return kept;
  }
  return draws.size();
}

}  // namespace krp
