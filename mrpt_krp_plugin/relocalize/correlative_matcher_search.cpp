// SPDX-License-Identifier: BSD-3-Clause
// The matcher's resumable best-first search (CorrelativeMatcher::Search): one solution, every
// candidate charged the request's leaf_penalty, run in slices by resume(). The exact depth-first
// match() and the bounds both searches share are in correlative_matcher.cpp.
#include <stdexcept>

#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"

namespace krp {

std::unique_ptr<CorrelativeMatcher::Search> CorrelativeMatcher::startSearch(const mrpt::obs::CObservation2DRangeScan& scan,
                                                                          const MatchRequest& request) const {
  // The last-search counters follow this search from here, not the match() before it.
  countAfresh();
  return setUpSearch(scan, request);
}

std::unique_ptr<CorrelativeMatcher::Search> CorrelativeMatcher::setUpSearch(const mrpt::obs::CObservation2DRangeScan& scan,
                                                                          const MatchRequest& request) const {
  if (!request.leaf_penalty) throw std::invalid_argument("CorrelativeMatcher::startSearch: the request has no leaf_penalty");
  if (request.solutions.value_or(params_.solutions) != 1)
    throw std::invalid_argument("CorrelativeMatcher::startSearch: one solution per search");
  auto search = std::unique_ptr<Search>(new Search());
  search->request_ = request;
  search->region_sum_ = regionSum(request.region);
  search->bar_ = request.min_score.value_or(params_.min_score);
  const auto points = returns(scan);
  if (points.size() < 3) {
    search->finished_ = true;
    return search;
  }
  search->rotations_ = rotationsOf(points, scan, request);
  return search;
}

bool CorrelativeMatcher::resume(Search& s, long long max_nodes) const {
  if (s.finished_) return true;
  // Best first, not depth first: with a low bar, depth first would charge every candidate that
  // clears the bar, most of which a better place outscores.
  const long long nodes_before = nodes_scored_;
  const auto scored = [&] { return s.nodes_ + (nodes_scored_ - nodes_before); };
  const InRegion in_region = [&s](int cx, int cy, int level) {
    return windowHoldsRegion(s.region_sum_, cx, cy, level);
  };
  const auto solution = [&](const Search::Entry& e) {
    return MatchSolution{poseOf(e.node.cx, e.node.cy, s.rotations_[e.rotation].phi), e.key};
  };
  const auto finish = [&](std::optional<MatchSolution> answer) {
    s.nodes_ = scored();
    s.solution_ = std::move(answer);
    s.finished_ = true;
    s.queue_ = {};
    s.tails_ = {};
    return true;
  };
  if (!s.rooted_) {
    for (size_t k = 0; k < s.rotations_.size(); ++k)
      for (const auto& r : roots(s.rotations_[k], in_region, s.bar_, s.tails_))
        if (r.bound > s.bar_) s.queue_.push({r.bound, static_cast<int>(k), r, false});
    s.rooted_ = true;
  }
  const long long budget = s.request_.max_nodes_scored;
  const long long slice_end = max_nodes > 0 ? scored() + max_nodes : 0;
  while (!s.queue_.empty()) {
    const Search::Entry& top = s.queue_.top();
    if (top.charged) return finish(solution(top));  // the top: it beats every bound left
    if (top.key <= s.floor()) {                      // queued before a better place was charged
      s.queue_.pop();
      continue;
    }
    if (budget > 0 && scored() >= budget) {
      // Out of budget: the best place charged so far is a true answer, maybe not the best.
      s.cut_short_ = true;
      cut_short_ = true;  // lastSearchCutShort() follows the search last begun, or match()
      return finish(s.best_ ? std::optional<MatchSolution>(solution(*s.best_)) : std::nullopt);
    }
    if (slice_end > 0 && scored() >= slice_end) {
      s.nodes_ = scored();
      return false;  // paused with this node still queued: the next slice starts from it
    }
    const Search::Entry e = top;
    s.queue_.pop();
    const Node& n = e.node;
    const Rotation& rot = s.rotations_[e.rotation];
    if (n.level == 0) {
      if (!isCandidate(n.cx, n.cy, s.region_sum_, s.request_.excluded)) continue;
      const double penalty = s.request_.leaf_penalty(poseOf(n.cx, n.cy, rot.phi), n.bound - s.floor());
      if (!(penalty >= 0.0)) throw std::invalid_argument("CorrelativeMatcher::match: leaf_penalty must be >= 0");
      if (n.bound - penalty > s.floor()) {
        s.best_ = Search::Entry{n.bound - penalty, e.rotation, n, true};
        s.queue_.push(*s.best_);
      }
      continue;
    }
    std::array<Node, 4> below;
    const size_t count = children(rot, n, s.tails_, in_region, s.floor(), s.tails_, below);
    for (size_t i = 0; i < count; ++i)
      if (below[i].bound > s.floor()) s.queue_.push({below[i].bound, e.rotation, below[i], false});
  }
  return finish(std::nullopt);
}

}  // namespace krp
