// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/rival_test.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose3D.h>

#include <limits>
#include <stdexcept>

namespace krp {

void validateRivalTestParams(const RivalTestParams& params) {
  if (!(params.decisive_log_ratio > 0.0)) throw std::invalid_argument("RivalTest: decisive_log_ratio must be > 0");
  if (params.refine_step_m < 0.0 || params.refine_step_deg < 0.0)
    throw std::invalid_argument("RivalTest: refinement steps must be >= 0");
}

RivalTest::RivalTest(const mrpt::math::TPose2D& rival, RivalTestParams params) : rival_(rival), params_(params) {
  validateRivalTestParams(params_);
}

void RivalTest::move(const mrpt::poses::CPose2D& increment) {
  rival_ = (mrpt::poses::CPose2D(rival_) + increment).asTPose();
}

double RivalTest::refinedLogLikelihood(const mrpt::maps::COccupancyGridMap2D& map,
                                       const mrpt::obs::CObservation2DRangeScan& scan, mrpt::math::TPose2D& pose,
                                       const SeeThroughPenalty::Scan* see_through) const {
  const bool charge_in_fit = see_through && params_.refit_charges_see_through;
  const double step_rad = params_.refine_step_deg * M_PI / 180.0;
  double best = -std::numeric_limits<double>::infinity();
  mrpt::math::TPose2D best_pose = pose;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dphi = -1; dphi <= 1; ++dphi) {
        const mrpt::math::TPose2D p(pose.x + dx * params_.refine_step_m, pose.y + dy * params_.refine_step_m,
                                    mrpt::math::wrapToPi(pose.phi + dphi * step_rad));
        double ll = map.computeObservationLikelihood(scan, mrpt::poses::CPose3D(mrpt::poses::CPose2D(p)));
        if (charge_in_fit) ll -= see_through->nats(p);
        if (ll > best) {
          best = ll;
          best_pose = p;
        }
      }
  pose = best_pose;
  return see_through && !charge_in_fit ? best - see_through->nats(best_pose) : best;
}

RivalTest::Verdict RivalTest::update(const mrpt::maps::COccupancyGridMap2D& map,
                                     const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& tracked,
                                     const SeeThroughPenalty::Scan* see_through) {
  mrpt::math::TPose2D refined_tracked = tracked;
  log_ratio_ += refinedLogLikelihood(map, scan, refined_tracked, see_through) - refinedLogLikelihood(map, scan, rival_, see_through);
  if (log_ratio_ >= params_.decisive_log_ratio) return Verdict::tracked_wins;
  if (log_ratio_ <= -params_.decisive_log_ratio) return Verdict::rival_wins;
  return Verdict::undecided;
}

}  // namespace krp
