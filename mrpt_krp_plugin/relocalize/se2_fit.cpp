// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/se2_fit.h"

#include <cmath>
#include <stdexcept>

namespace krp {

namespace {
// Below this the robot points coincide and no heading can be recovered [m^2].
constexpr double kMinSpread = 1e-12;
}  // namespace

double residualM(const mrpt::math::TPose2D& pose, const Correspondence2D& c) {
  return (pose.composePoint(c.robot) - c.map).norm();
}

Se2Fit fitSe2(const std::vector<Correspondence2D>& corrs, const Se2FitParams& params) {
  if (corrs.size() < 2) throw std::invalid_argument("fitSe2: needs at least two correspondences");
  double w_sum = 0, px = 0, py = 0, qx = 0, qy = 0;
  for (const auto& c : corrs) {
    w_sum += c.weight;
    px += c.weight * c.robot.x;
    py += c.weight * c.robot.y;
    qx += c.weight * c.map.x;
    qy += c.weight * c.map.y;
  }
  if (!(w_sum > 0)) throw std::invalid_argument("fitSe2: weights must be positive");
  px /= w_sum, py /= w_sum, qx /= w_sum, qy /= w_sum;
  double dot = 0, cross = 0, spread = 0;
  for (const auto& c : corrs) {
    const double ax = c.robot.x - px, ay = c.robot.y - py, bx = c.map.x - qx, by = c.map.y - qy;
    dot += c.weight * (ax * bx + ay * by);
    cross += c.weight * (ax * by - ay * bx);
    spread += c.weight * (ax * ax + ay * ay);
  }
  if (spread < kMinSpread) throw std::invalid_argument("fitSe2: the robot points coincide");
  Se2Fit fit;
  const double phi = std::atan2(cross, dot), cs = std::cos(phi), sn = std::sin(phi);
  fit.pose = {qx - (cs * px - sn * py), qy - (sn * px + cs * py), phi};

  double sq = 0;
  for (const auto& c : corrs) sq += c.weight * std::pow(residualM(fit.pose, c), 2);
  fit.rms_m = std::sqrt(sq / w_sum);
  // Each correspondence gives two equations for three unknowns: the unbiased variance
  // divides by the redundancy 2n - 3, floored so that an exact fit is not called certain.
  const double n = static_cast<double>(corrs.size());
  const double redundancy = 2.0 * n - 3.0;
  const double var = std::max(redundancy > 0 ? sq / w_sum * n / redundancy : 0.0,
                              params.min_point_std_m * params.min_point_std_m);
  // Information matrix of the linearized residuals: d(residual)/d(x, y, phi) = [I | R' p].
  mrpt::math::CMatrixDouble33 info;
  info.setZero();
  for (const auto& c : corrs) {
    const double jx = -sn * c.robot.x - cs * c.robot.y, jy = cs * c.robot.x - sn * c.robot.y;
    const double w = c.weight / w_sum * n / var;  // weights relative to their mean
    info(0, 0) += w, info(1, 1) += w;
    info(0, 2) += w * jx, info(1, 2) += w * jy;
    info(2, 2) += w * (jx * jx + jy * jy);
  }
  info(2, 0) = info(0, 2), info(2, 1) = info(1, 2);
  fit.cov = info.inverse_LLt();
  return fit;
}

}  // namespace krp
