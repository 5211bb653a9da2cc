// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/path_ambiguity.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace krp {

void validatePathAmbiguityParams(const PathAmbiguityParams& params) {
  if (!(params.first_scan_margin >= 0.0 && params.first_scan_margin <= 1.0))
    throw std::invalid_argument("PathAmbiguityParams: first_scan_margin must be in [0, 1]");
  if (params.max_places < 0) throw std::invalid_argument("PathAmbiguityParams: max_places must be >= 0");
  validatePlaceTrackerParams(params.tracking);
  if (!(params.decisive_log_ratio > 0.0)) throw std::invalid_argument("PathAmbiguityParams: decisive_log_ratio must be > 0");
  if (!(params.truth_offset_steps >= 0.0 && params.truth_offset_steps <= 0.5))
    throw std::invalid_argument("PathAmbiguityParams: truth_offset_steps must be in [0, 0.5]");
}

std::string toString(PathVerdict verdict) {
  switch (verdict) {
    case PathVerdict::not_checked: return "not_checked";
    case PathVerdict::told_apart: return "told_apart";
    case PathVerdict::ambiguous: return "ambiguous";
    case PathVerdict::misleading: return "misleading";
  }
  return "unknown";
}

PathAmbiguityCheck::PathAmbiguityCheck(std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map,
                                       std::shared_ptr<const CorrelativeMatcher> matcher,
                                       std::shared_ptr<const SeeThroughPenalty> see_through, PathAmbiguityParams params)
    : map_(std::move(map)), matcher_(std::move(matcher)), see_through_(std::move(see_through)), params_(params) {
  validatePathAmbiguityParams(params_);
  if (!map_ || !matcher_) throw std::invalid_argument("PathAmbiguityCheck: needs a map and a matcher");
}

PathAmbiguity PathAmbiguityCheck::check(const std::vector<mrpt::math::TPose2D>& truth,
                                        const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans,
                                        const std::vector<EndPlace>& ends) const {
  if (truth.empty() || truth.size() != scans.size())
    throw std::invalid_argument("PathAmbiguityCheck: one true pose per scan, at least one");
  const auto& start = truth.front();
  std::vector<mrpt::math::TPose2D> place_starts;
  std::vector<std::string> sources;
  if (params_.max_places > 0) {
    MatchRequest request;
    request.min_score = std::max(0.0, matcher_->scoreAt(*scans.front(), start) - params_.first_scan_margin);
    request.solutions = params_.max_places;
    request.excluded = {mrpt::math::TPoint2D(start.x, start.y)};
    for (const auto& p : matcher_->match(*scans.front(), request)) {
      place_starts.push_back(p.pose);
      sources.emplace_back("first_scan");
    }
  }
  PathAmbiguity out;
  // The twin robot that ends at `end` started at end (+) (truth's whole motion)^-1.
  const mrpt::poses::CPose2D undo_path = mrpt::poses::CPose2D() - (mrpt::poses::CPose2D(truth.back()) - mrpt::poses::CPose2D(start));
  const double exclusion = matcher_->params().exclusion_m;
  const auto weighed_already = [&](const mrpt::math::TPose2D& p) {
    if (std::hypot(p.x - start.x, p.y - start.y) < exclusion) return true;
    return std::any_of(place_starts.begin(), place_starts.end(),
                       [&](const mrpt::math::TPose2D& q) { return std::hypot(p.x - q.x, p.y - q.y) < exclusion; });
  };
  for (const auto& end : ends) {
    const auto twin_start = (mrpt::poses::CPose2D(end.pose) + undo_path).asTPose();
    if (weighed_already(twin_start)) continue;
    place_starts.push_back(twin_start);
    sources.push_back(end.source);
    ++out.end_places;
  }
  out.places = static_cast<int>(place_starts.size());
  if (place_starts.empty()) {
    out.verdict = PathVerdict::told_apart;
    out.closest_log_ratio = std::numeric_limits<double>::infinity();
    return out;
  }
  // The truth first: the tracker keeps its places in order.
  const auto& steps = params_.tracking;
  const double off = params_.truth_offset_steps;
  std::vector<mrpt::math::TPose2D> starts{
      {start.x + off * steps.refine_step_m, start.y + off * steps.refine_step_m,
       mrpt::math::wrapToPi(start.phi + off * steps.refine_step_deg * M_PI / 180.0)}};
  starts.insert(starts.end(), place_starts.begin(), place_starts.end());
  PlaceTracker tracker(params_.tracking);
  for (size_t i = 0; i < scans.size(); ++i) {
    std::optional<SeeThroughPenalty::Scan> charged;
    if (see_through_) charged = see_through_->forScan(*scans[i]);
    const SeeThroughPenalty::Scan* charge = charged ? &*charged : nullptr;
    if (i == 0) {
      tracker.start(*map_, *scans[i], starts, charge);
    } else {
      // The twin robot drives the truth's own path from its place.
      tracker.move(mrpt::poses::CPose2D(truth[i]) - mrpt::poses::CPose2D(truth[i - 1]));
      tracker.update(*map_, *scans[i], charge);
    }
  }
  const auto& weighed = tracker.places();
  size_t closest = 1;
  for (size_t k = 2; k < weighed.size(); ++k)
    if (weighed[k].log_likelihood > weighed[closest].log_likelihood) closest = k;
  out.closest_log_ratio = weighed.front().log_likelihood - weighed[closest].log_likelihood;
  out.closest_distance_m = std::hypot(place_starts[closest - 1].x - start.x, place_starts[closest - 1].y - start.y);
  out.closest_source = sources[closest - 1];
  const double bar = params_.decisive_log_ratio;
  out.verdict = out.closest_log_ratio >= bar    ? PathVerdict::told_apart
                : out.closest_log_ratio <= -bar ? PathVerdict::misleading
                                                : PathVerdict::ambiguous;
  return out;
}

}  // namespace krp
