// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/look_alike_guard.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace krp {

LookAlikeGuard::LookAlikeGuard(std::shared_ptr<const CorrelativeMatcher> matcher, LookAlikeGuardParams params)
    : matcher_(std::move(matcher)), params_(params) {
  if (!matcher_) throw std::invalid_argument("LookAlikeGuard: no matcher");
  if (params_.moved_share <= 0.0 || params_.moved_share > 1.0)
    throw std::invalid_argument("LookAlikeGuard: moved_share must be in (0, 1]");
  if (params_.score_margin < 0.0 || params_.score_margin > 1.0 || params_.ambiguity_margin < 0.0 ||
      params_.ambiguity_margin > 1.0)
    throw std::invalid_argument("LookAlikeGuard: score_margin and ambiguity_margin must be in [0, 1]");
  if (params_.ambiguity_margin < params_.score_margin)
    throw std::invalid_argument("LookAlikeGuard: ambiguity_margin must be at least score_margin");
  if (params_.recheck_every_updates < 0 || params_.remembered_rejected < 0)
    throw std::invalid_argument("LookAlikeGuard: recheck_every_updates and remembered_rejected must be 0 or more");
  if (params_.recheck_every_updates > LookAlikeGuardParams::kMaxRecheckEveryUpdates)
    throw std::invalid_argument("LookAlikeGuard: recheck_every_updates must be at most " +
                                std::to_string(LookAlikeGuardParams::kMaxRecheckEveryUpdates));
  if (params_.history_updates < 0) throw std::invalid_argument("LookAlikeGuard: history_updates must be 0 or more");
  if (params_.max_search_nodes < 0 || params_.max_search_nodes > LookAlikeGuardParams::kMaxSearchNodesLimit)
    throw std::invalid_argument("LookAlikeGuard: max_search_nodes must be 0 (no limit) to " +
                                std::to_string(LookAlikeGuardParams::kMaxSearchNodesLimit));
  if (params_.max_nodes_per_update < 0 || params_.max_nodes_per_update > LookAlikeGuardParams::kMaxSearchNodesLimit)
    throw std::invalid_argument("LookAlikeGuard: max_nodes_per_update must be 0 (no limit) to " +
                                std::to_string(LookAlikeGuardParams::kMaxSearchNodesLimit));
  if (!MatchRequest::validWallHeadingWindow(params_.wall_heading_window_deg))
    throw std::invalid_argument("LookAlikeGuard: wall_heading_window_deg must be " +
                                MatchRequest::wallHeadingWindowRange());
  if (params_.searches_per_update < 1) throw std::invalid_argument("LookAlikeGuard: searches_per_update must be at least 1");
  if (!(params_.min_fit_fraction >= 0.0 && params_.min_fit_fraction <= 1.0))
    throw std::invalid_argument("LookAlikeGuard: min_fit_fraction must be in [0, 1]");
  if (isConcentrated({params_.unexplained_xy_std_m, params_.unexplained_phi_std_deg}, params_.converged))
    throw std::invalid_argument("LookAlikeGuard: an unexplained scan's spread (unexplained_xy_std_m, "
                                "unexplained_phi_std_deg) must not read as converged");
  validateRivalTestParams(params_.rival_test);  // refused here, not mid-run
  if (!(params_.reopen_log_ratio < params_.rival_test.decisive_log_ratio))
    throw std::invalid_argument("LookAlikeGuard: reopen_log_ratio must be below rival_test.decisive_log_ratio");
}

double LookAlikeGuard::score(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose,
                             const SeeThroughPenalty::Scan* see_through) const {
  const auto* charged = searchCharge(see_through);
  return matcher_->scoreAt(scan, pose) - (charged ? charged->share(pose) : 0.0);
}

LookAlikeSearch LookAlikeGuard::search(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose,
                                       const std::vector<mrpt::math::TPoint2D>& also_excluded,
                                       const SeeThroughPenalty::Scan* see_through) const {
  // Run to its end before this returns, the search may use the caller's charge: no copy.
  auto in_progress = beginSearch(scan, pose, also_excluded, see_through, /*own_charge=*/false);
  return resume(*in_progress, 0);
}

long long LookAlikeSearchInProgress::nodesScored() const { return charged_ ? charged_->nodesScored() : 0; }

std::unique_ptr<LookAlikeSearchInProgress> LookAlikeGuard::startSearch(
    const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose,
    const std::vector<mrpt::math::TPoint2D>& also_excluded, const SeeThroughPenalty::Scan* see_through) const {
  return beginSearch(scan, pose, also_excluded, see_through, /*own_charge=*/true);
}

std::unique_ptr<LookAlikeSearchInProgress> LookAlikeGuard::beginSearch(
    const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose,
    const std::vector<mrpt::math::TPoint2D>& also_excluded, const SeeThroughPenalty::Scan* see_through,
    bool own_charge) const {
  std::unique_ptr<LookAlikeSearchInProgress> s(new LookAlikeSearchInProgress());
  s->tracked_score_ = score(scan, pose, see_through);
  MatchRequest request;
  request.min_score = lookAlikeBar(s->tracked_score_);
  request.solutions = 1;
  request.excluded = {{pose.x, pose.y}};  // the tracked place found again is no alternative to it
  request.excluded.insert(request.excluded.end(), also_excluded.begin(), also_excluded.end());
  request.max_nodes_scored = params_.max_search_nodes;
  request.wall_heading_window_deg = params_.wall_heading_window_deg;
  if (const auto* charged = searchCharge(see_through)) {
    const SeeThroughPenalty::Scan* used = charged;
    if (own_charge) {
      s->see_through_ = std::make_unique<SeeThroughPenalty::Scan>(*charged);
      used = s->see_through_.get();
    }
    request.leaf_penalty = [used](const mrpt::math::TPose2D& p, double enough) { return used->shareUpTo(p, enough); };
    s->charged_ = matcher_->startSearch(scan, request);
    return s;
  }
  const auto found = matcher_->match(scan, request);
  s->uncharged_.cut_short = matcher_->lastSearchCutShort();
  if (!found.empty()) s->uncharged_.found = LookAlike{found.front().pose, found.front().score, s->tracked_score_};
  return s;
}

LookAlikeSearch LookAlikeGuard::resume(LookAlikeSearchInProgress& search, long long max_nodes) const {
  if (!search.charged_) return search.uncharged_;
  LookAlikeSearch out;
  if (!matcher_->resume(*search.charged_, max_nodes)) {
    out.paused = true;
    return out;
  }
  out.cut_short = search.charged_->cutShort();
  if (const auto& found = search.charged_->solution())
    out.found = LookAlike{found->pose, found->score, search.tracked_score_};
  return out;
}

bool LookAlikeGuard::isLookAlike(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& place,
                                 const mrpt::math::TPose2D& tracked, const SeeThroughPenalty::Scan* see_through) const {
  // The search's bar: a place the matcher would not report is no look-alike, however badly the
  // tracked pose fits too (right after a kidnap both fit nothing).
  return score(scan, place, see_through) >= lookAlikeBar(score(scan, tracked, see_through));
}

double LookAlikeGuard::lookAlikeBar(double tracked_score) const {
  return std::max(tracked_score - params_.ambiguity_margin, matcher_->params().min_score);
}

bool LookAlikeGuard::samePlace(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) const {
  return std::hypot(a.x - b.x, a.y - b.y) < matcher_->params().exclusion_m;
}

mrpt::math::CMatrixDouble33 covarianceWithLookAlike(const mrpt::math::CMatrixDouble33& cov, const mrpt::math::TPose2D& mean,
                                                    const mrpt::math::TPose2D& other) {
  const double d[3] = {other.x - mean.x, other.y - mean.y, mrpt::math::wrapToPi(other.phi - mean.phi)};
  auto out = cov;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out(i, j) += 0.5 * d[i] * d[j];
  return out;
}

}  // namespace krp
