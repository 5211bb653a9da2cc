// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/rival_test.h"

#include <stdexcept>

#include "mrpt_krp_plugin/filter/pose_grid_fit.h"

namespace krp {

void validateRivalTestParams(const RivalTestParams& params) {
  if (!(params.decisive_log_ratio > 0.0)) throw std::invalid_argument("RivalTest: decisive_log_ratio must be > 0");
  if (params.refine_step_m < 0.0 || params.refine_step_deg < 0.0)
    throw std::invalid_argument("RivalTest: refinement steps must be >= 0");
  if (params.finer_refinements < 0) throw std::invalid_argument("RivalTest: finer_refinements must be 0 or more");
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
  const PoseGrid grid{params_.refine_step_m, params_.refine_step_deg, 1, 1};
  const auto fit = refinedPoseOnGrids(map, scan, pose, grid, params_.finer_refinements, charge_in_fit ? see_through : nullptr);
  pose = fit.pose;
  return see_through && !charge_in_fit ? fit.score - see_through->nats(fit.pose) : fit.score;
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
