// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/CMatrixFixed.h>

namespace krp {

/// How spread out a pose estimate is, read from its covariance.
struct FilterSpread {
  double xy_std_m = 0.0;     ///< sqrt of the largest eigenvalue of the xy block: the worst direction [m]
  double phi_std_deg = 0.0;  ///< heading std [deg]
};

FilterSpread filterSpread(const mrpt::math::CMatrixDouble33& cov);

/// Below these an estimate reads as a pose rather than a search: the filter counts as converged
/// (the look-alike guard checks it) and the bench counts it as confident.
struct ConcentrationThresholds {
  double xy_std_m = 0.5;      ///< [m]
  double phi_std_deg = 10.0;  ///< [deg]
};

/// Both stds below their thresholds.
bool isConcentrated(const FilterSpread& spread, const ConcentrationThresholds& thresholds);

/// `cov` with its x, y and heading variances raised to at least these stds' squares (what is
/// already wider stays), so that filterSpread reads at least `xy_std_m` and `phi_std_deg`.
mrpt::math::CMatrixDouble33 covarianceWithSpreadAtLeast(const mrpt::math::CMatrixDouble33& cov, double xy_std_m,
                                                        double phi_std_deg);

}  // namespace krp
