// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/filter_spread.h"

#include <algorithm>
#include <cmath>

namespace krp {

FilterSpread filterSpread(const mrpt::math::CMatrixDouble33& cov) {
  // The largest eigenvalue of the 2x2 xy block, in closed form: a cloud stretched along a
  // diagonal is as spread as one stretched along an axis.
  const double a = cov(0, 0), b = cov(0, 1), d = cov(1, 1);
  const double lambda = 0.5 * (a + d) + std::sqrt(0.25 * (a - d) * (a - d) + b * b);
  FilterSpread s;
  s.xy_std_m = std::sqrt(std::max(0.0, lambda));
  s.phi_std_deg = std::sqrt(std::max(0.0, cov(2, 2))) * 180.0 / M_PI;
  return s;
}

bool isConcentrated(const FilterSpread& spread, const ConcentrationThresholds& thresholds) {
  return spread.xy_std_m < thresholds.xy_std_m && spread.phi_std_deg < thresholds.phi_std_deg;
}

mrpt::math::CMatrixDouble33 covarianceWithSpreadAtLeast(const mrpt::math::CMatrixDouble33& cov, double xy_std_m,
                                                        double phi_std_deg) {
  // A diagonal entry never exceeds the block's largest eigenvalue, so raising the diagonal is enough.
  auto wide = cov;
  const double phi_std_rad = phi_std_deg * M_PI / 180.0;
  wide(0, 0) = std::max(wide(0, 0), xy_std_m * xy_std_m);
  wide(1, 1) = std::max(wide(1, 1), xy_std_m * xy_std_m);
  wide(2, 2) = std::max(wide(2, 2), phi_std_rad * phi_std_rad);
  return wide;
}

}  // namespace krp
