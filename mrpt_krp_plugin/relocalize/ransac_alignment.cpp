// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/ransac_alignment.h"

#include <cmath>
#include <utility>

#include "mrpt_krp_plugin/common/random.h"

namespace krp {

namespace {

double distance(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

struct Support {
  std::vector<int> inliers;
  double weight = 0.0;
};

Support supportOf(const mrpt::math::TPose2D& pose, const std::vector<Correspondence2D>& corrs, double threshold) {
  Support s;
  for (int i = 0; i < static_cast<int>(corrs.size()); ++i) {
    if (residualM(pose, corrs[i]) <= threshold) {
      s.inliers.push_back(i);
      s.weight += corrs[i].weight;
    }
  }
  return s;
}

std::vector<std::pair<int, int>> candidatePairs(const std::vector<Correspondence2D>& corrs,
                                                const RansacAlignmentParams& p) {
  const int n = static_cast<int>(corrs.size());
  std::vector<std::pair<int, int>> all;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double dr = distance(corrs[i].robot, corrs[j].robot), dm = distance(corrs[i].map, corrs[j].map);
      if (dr < p.min_pair_separation_m || std::abs(dr - dm) > p.pair_distance_tolerance_m) continue;
      all.emplace_back(i, j);
    }
  }
  if (static_cast<int>(all.size()) <= p.max_pairs) return all;
  // Too many to try them all: a seeded random subset.
  Rng(p.seed).sampleToFront(all, static_cast<std::size_t>(p.max_pairs));
  all.resize(p.max_pairs);
  return all;
}

}  // namespace

std::optional<AlignmentResult> alignRansac(const std::vector<Correspondence2D>& corrs,
                                           const RansacAlignmentParams& params) {
  Support best;
  mrpt::math::TPose2D best_pose;
  for (const auto& [i, j] : candidatePairs(corrs, params)) {
    const auto pose = fitSe2({corrs[i], corrs[j]}, params.fit).pose;
    auto s = supportOf(pose, corrs, params.inlier_threshold_m);
    if (s.weight > best.weight) best = std::move(s), best_pose = pose;
  }
  if (static_cast<int>(best.inliers.size()) < std::max(params.min_inliers, 2)) return std::nullopt;

  AlignmentResult r;
  constexpr int kRefits = 2;
  for (int pass = 0; pass < kRefits; ++pass) {
    std::vector<Correspondence2D> in;
    for (int i : best.inliers) in.push_back(corrs[i]);
    r.fit = fitSe2(in, params.fit);
    r.inliers = best.inliers;
    r.inlier_weight = best.weight;
    best = supportOf(r.fit.pose, corrs, params.inlier_threshold_m);
    if (static_cast<int>(best.inliers.size()) < std::max(params.min_inliers, 2)) break;
  }
  return r;
}

}  // namespace krp
