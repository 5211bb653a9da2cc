// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/look_alike_guard.h"

#include <algorithm>
#include <stdexcept>

namespace krp {

LookAlikeGuard::LookAlikeGuard(std::shared_ptr<const CorrelativeMatcher> matcher, LookAlikeGuardParams params)
    : matcher_(std::move(matcher)), params_(params) {
  if (!matcher_) throw std::invalid_argument("LookAlikeGuard: no matcher");
  if (params_.moved_share <= 0.0 || params_.moved_share > 1.0)
    throw std::invalid_argument("LookAlikeGuard: moved_share must be in (0, 1]");
}

std::optional<mrpt::math::TPose2D> LookAlikeGuard::lookAlike(const mrpt::obs::CObservation2DRangeScan& scan,
                                                             const mrpt::math::TPose2D& pose) const {
  MatchRequest request;
  request.min_score = std::max(matcher_->scoreAt(scan, pose) - params_.score_margin, matcher_->params().min_score);
  request.solutions = 1;
  request.excluded = {{pose.x, pose.y}};  // the tracked place found again is no alternative to it
  const auto found = matcher_->match(scan, request);
  if (found.empty()) return std::nullopt;
  return found.front().pose;
}

}  // namespace krp
