// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"

#include <mrpt/math/wrap2pi.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mrpt_krp_plugin/submap/scan_beams.h"

namespace krp {

CorrelativeMatcher::CorrelativeMatcher(const mrpt::maps::COccupancyGridMap2D& map, CorrelativeMatcherParams params)
    : params_(params), x_min_(map.getXMin()), y_min_(map.getYMin()) {
  const double res = params_.resolution_m;
  const int w = std::max(1, static_cast<int>(std::ceil((map.getXMax() - x_min_) / res)));
  const int h = std::max(1, static_cast<int>(std::ceil((map.getYMax() - y_min_) / res)));
  // Obstacles and free space resampled onto the search grid (getPos is p(free)).
  cv::Mat not_obstacle(h, w, CV_8U, cv::Scalar(255));
  free_ = cv::Mat::zeros(h, w, CV_8U);
  for (int cy = 0; cy < static_cast<int>(map.getSizeY()); ++cy) {
    for (int cx = 0; cx < static_cast<int>(map.getSizeX()); ++cx) {
      const int gx = std::min(w - 1, static_cast<int>((map.idx2x(cx) - x_min_) / res));
      const int gy = std::min(h - 1, static_cast<int>((map.idx2y(cy) - y_min_) / res));
      const double p_free = map.getCell(cx, cy);
      if (1.0 - p_free > params_.min_occupancy) not_obstacle.at<uint8_t>(gy, gx) = 0;
      if (p_free >= params_.min_freeness) free_.at<uint8_t>(gy, gx) = 1;
    }
  }
  free_.setTo(0, not_obstacle == 0);  // a cell holding any obstacle is no place to stand
  cv::Mat dist;
  cv::distanceTransform(not_obstacle, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  dist *= res;
  cv::Mat score;
  cv::multiply(dist, dist, score, -0.5 / (params_.hit_sigma_m * params_.hit_sigma_m));
  cv::exp(score, score);
  if (!(params_.margin_m >= 0.0)) throw std::invalid_argument("CorrelativeMatcherParams::margin_m must be >= 0");
  margin_ = static_cast<int>(std::ceil(params_.margin_m / res));
  cv::copyMakeBorder(score, score, margin_, margin_, margin_, margin_, cv::BORDER_CONSTANT, cv::Scalar(0));
  levels_.push_back(score);
  const int rows = score.rows, cols = score.cols;
  for (int lvl = 1; lvl <= params_.depth; ++lvl) {
    // Window doubling: the max over [x, x + 2s) is the max of two windows of s.
    const int s = 1 << (lvl - 1);
    const cv::Mat& prev = levels_.back();
    cv::Mat next = prev.clone();
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < cols; ++x) {
        float m = prev.at<float>(y, x);
        if (x + s < cols) m = std::max(m, prev.at<float>(y, x + s));
        if (y + s < rows) m = std::max(m, prev.at<float>(y + s, x));
        if (x + s < cols && y + s < rows) m = std::max(m, prev.at<float>(y + s, x + s));
        next.at<float>(y, x) = m;
      }
    levels_.push_back(next);
  }
  for (const auto& level : levels_) CV_Assert(level.isContinuous());  // Rotation::linear indexes them
  map_axes_ = mapWallAxes(map, params_.wall_axes);
}

cv::Mat CorrelativeMatcher::regionOf(const std::vector<Zone>& zones) const {
  cv::Mat region = cv::Mat::zeros(free_.size(), CV_8U);
  const double res = params_.resolution_m;
  for (const auto& z : zones) {
    std::vector<cv::Point> outline;
    for (const auto& p : z.polygon)
      outline.emplace_back(static_cast<int>(std::floor((p.x - x_min_) / res)), static_cast<int>(std::floor((p.y - y_min_) / res)));
    cv::fillPoly(region, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(1));
  }
  return region;
}

std::vector<mrpt::math::TPoint2D> CorrelativeMatcher::returns(const mrpt::obs::CObservation2DRangeScan& scan) const {
  std::vector<mrpt::math::TPoint2D> points;
  const mrpt::poses::CPose2D sensor(scan.sensorPose);
  for (const auto& b : scanBeams(scan).beams) {
    if (!b.hit) continue;
    const auto p = sensor + mrpt::poses::CPose2D(b.range_m * std::cos(b.angle_rad), b.range_m * std::sin(b.angle_rad), 0);
    points.emplace_back(p.x(), p.y());
  }
  if (static_cast<int>(points.size()) > params_.max_points) {
    std::vector<mrpt::math::TPoint2D> kept;
    for (int i = 0; i < params_.max_points; ++i) kept.push_back(points[i * points.size() / params_.max_points]);
    points.swap(kept);
  }
  return points;
}

CorrelativeMatcher::Rotation CorrelativeMatcher::rotate(const std::vector<mrpt::math::TPoint2D>& points, double phi) const {
  Rotation r{phi, {}, {}};
  const double res = params_.resolution_m, c = std::cos(phi), s = std::sin(phi);
  // Every level grid has the score grid's size and is continuous, so one row stride serves all.
  const int stride = levels_.front().cols;
  for (const auto& p : points) {
    const cv::Point o(static_cast<int>(std::floor(0.5 + (c * p.x - s * p.y) / res)),
                      static_cast<int>(std::floor(0.5 + (s * p.x + c * p.y) / res)));
    r.offsets.push_back(o);
    r.linear.push_back(o.y * stride + o.x);
    r.min_x = std::min(r.min_x, o.x);
    r.max_x = std::max(r.max_x, o.x);
    r.min_y = std::min(r.min_y, o.y);
    r.max_y = std::max(r.max_y, o.y);
  }
  return r;
}

double CorrelativeMatcher::scoreAt(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose) const {
  const auto points = returns(scan);
  if (points.size() < 3) return 0.0;
  const int cx = static_cast<int>(std::floor((pose.x - x_min_) / params_.resolution_m));
  const int cy = static_cast<int>(std::floor((pose.y - y_min_) / params_.resolution_m));
  const long long nodes = nodes_scored_;
  const double score = bound(rotate(points, pose.phi), cx, cy, 0);
  nodes_scored_ = nodes;  // not part of any search's cost
  return score;
}

std::vector<MatchSolution> CorrelativeMatcher::match(const mrpt::obs::CObservation2DRangeScan& scan,
                                                     const MatchRequest& request) const {
  countAfresh();
  const int solutions = request.solutions.value_or(params_.solutions);
  std::vector<MatchSolution> out;
  if (request.leaf_penalty) {
    // Each solution a search of its own, the ones found before excluded.
    MatchRequest one = request;
    one.solutions = 1;
    for (int sol = 0; sol < solutions; ++sol) {
      // setUpSearch, not startSearch: this match() counts all of its searches.
      const auto search = setUpSearch(scan, one);
      resume(*search, 0);
      if (!search->solution()) break;
      out.push_back(*search->solution());
      one.excluded.emplace_back(out.back().pose.x, out.back().pose.y);
    }
    return out;
  }
  const cv::Mat region_sum = regionSum(request.region);
  const InRegion in_region = [&](int cx, int cy, int level) { return windowHoldsRegion(region_sum, cx, cy, level); };
  const auto points = returns(scan);
  if (points.size() < 3) return {};
  const auto rotations = rotationsOf(points, scan, request);

  const double bar = request.min_score.value_or(params_.min_score);
  auto excluded = request.excluded;  // and every solution found, as each search ends
  // Where look-alikes abound, an earlier search passes through some on its way to its best: a
  // later one that starts from the best of those still allowed prunes most of its tree at once.
  std::vector<Improvement> passed;
  for (int sol = 0; sol < solutions; ++sol) {
    const Candidate candidate = [&](int cx, int cy) { return isCandidate(cx, cy, region_sum, excluded); };
    std::optional<MatchSolution> start;
    for (const auto& p : passed)
      if ((!start || p.solution.score > start->score) && candidate(p.cx, p.cy)) start = p.solution;
    const bool warm = params_.warm_start_later_solutions && sol + 1 < solutions;
    const auto best = searchDepthFirst(rotations, bar, in_region, candidate,
                                       params_.warm_start_later_solutions ? start : std::nullopt,
                                       warm ? &passed : nullptr);
    if (!best) break;
    out.push_back(*best);
    excluded.emplace_back(best->pose.x, best->pose.y);
  }
  return out;
}

mrpt::math::TPose2D CorrelativeMatcher::poseOf(int cx, int cy, double phi) const {
  const double res = params_.resolution_m;
  return {x_min_ + (cx + 0.5) * res, y_min_ + (cy + 0.5) * res, phi};
}

std::vector<CorrelativeMatcher::Node> CorrelativeMatcher::roots(const Rotation& rot, const InRegion& in_region,
                                                                double cutoff, TailSums& tails) const {
  const int top = params_.depth, step = 1 << top;
  std::vector<Node> out;
  for (int cy = 0; cy < free_.rows; cy += step)
    for (int cx = 0; cx < free_.cols; cx += step)
      if (in_region(cx, cy, top)) out.push_back(Node{cx, cy, top, 0.0});
  boundNodes(rot, out.data(), out.size(), cutoff, nullptr, tails);
  return out;
}

size_t CorrelativeMatcher::children(const Rotation& rot, const Node& n, const TailSums& n_tails,
                                    const InRegion& in_region, double cutoff, TailSums& tails,
                                    std::array<Node, 4>& out) const {
  // Copied first: `tails` may be `n_tails`, and growing it would move them.
  std::array<float, kMaxCheckpoints> parent;  // written up to checkpoints(rot) before any read
  const float* parent_tail = nullptr;
  if (n.tail >= 0) {
    std::copy_n(n_tails.begin() + n.tail, checkpoints(rot), parent.begin());
    parent_tail = parent.data();
  }
  const int level = n.level - 1, half = 1 << level;
  size_t count = 0;
  for (int dy : {0, half})
    for (int dx : {0, half}) {
      const int cx = n.cx + dx, cy = n.cy + dy;
      if (cx >= free_.cols || cy >= free_.rows || !in_region(cx, cy, level)) continue;
      out[count++] = Node{cx, cy, level, 0.0};
    }
  boundNodes(rot, out.data(), count, cutoff, parent_tail, tails);
  return count;
}

std::optional<MatchSolution> CorrelativeMatcher::searchDepthFirst(const std::vector<Rotation>& rotations, double bar,
                                                                  const InRegion& in_region, const Candidate& candidate,
                                                                  const std::optional<MatchSolution>& start,
                                                                  std::vector<Improvement>* improvements) const {
  MatchSolution best = start.value_or(MatchSolution{{}, bar});
  bool found = start.has_value();
  const auto higher = [](const Node& a, const Node& b) { return a.bound > b.bound; };
  // The tail sums of the roots of every heading, and of the children of the node being expanded
  // at each level: depth-first, one node per level is expanded at a time.
  std::vector<TailSums> root_tails(rotations.size());
  std::vector<TailSums> child_tails(static_cast<size_t>(std::max(params_.depth, 1)));
  // Best child first; a node whose bound cannot beat the best is pruned.
  const auto visit = [&](const auto& self, const Rotation& rot, const Node& n, const TailSums& n_tails) -> void {
    if (n.bound <= best.score) return;
    if (n.level == 0) {
      if (!candidate(n.cx, n.cy)) return;
      best = {poseOf(n.cx, n.cy, rot.phi), n.bound};
      found = true;
      if (improvements) improvements->push_back({best, n.cx, n.cy});
      return;
    }
    std::array<Node, 4> below;
    // Stable, so a pruned child (sorted last, then skipped) leaves the others' order as it was.
    auto& tails = child_tails[static_cast<size_t>(n.level - 1)];
    tails.clear();
    const size_t count = children(rot, n, n_tails, in_region, best.score, tails, below);
    for (size_t i = 1; i < count; ++i)
      for (size_t j = i; j > 0 && higher(below[j], below[j - 1]); --j) std::swap(below[j], below[j - 1]);
    for (size_t i = 0; i < count; ++i) self(self, rot, below[i], tails);
  };
  // Every root's true bound: pruning some would change how the sort orders equal bounds, and with
  // it which of two equally good places is found first.
  struct Root {
    Node node;
    size_t rotation;
  };
  std::vector<Root> order;
  for (size_t k = 0; k < rotations.size(); ++k) {
    auto top = roots(rotations[k], in_region, kNoCutoff, root_tails[k]);
    std::sort(top.begin(), top.end(), higher);
    for (const auto& n : top) order.push_back({n, k});
  }
  // Stable: roots of equal bound keep the heading-after-heading order.
  if (params_.roots_across_headings)
    std::stable_sort(order.begin(), order.end(), [&](const Root& a, const Root& b) { return higher(a.node, b.node); });
  for (const auto& r : order) {
    // Across headings every root left bounds no higher; heading after heading, only its heading's.
    if (r.node.bound <= best.score) {
      if (params_.roots_across_headings) break;
      continue;
    }
    visit(visit, rotations[r.rotation], r.node, root_tails[r.rotation]);
  }
  if (!found) return std::nullopt;
  return best;
}

bool CorrelativeMatcher::windowHoldsRegion(const cv::Mat& region_sum, int cx, int cy, int level) {
  if (region_sum.empty()) return true;
  const int cols = region_sum.cols - 1, rows = region_sum.rows - 1;
  const int x1 = std::min(cx + (1 << level), cols), y1 = std::min(cy + (1 << level), rows);
  return region_sum.at<int>(y1, x1) - region_sum.at<int>(cy, x1) - region_sum.at<int>(y1, cx) +
             region_sum.at<int>(cy, cx) > 0;
}

cv::Mat CorrelativeMatcher::regionSum(const cv::Mat& region) const {
  if (region.empty()) return {};
  if (region.size() != free_.size() || region.type() != CV_8U)
    throw std::invalid_argument("CorrelativeMatcher::match: region not made by regionOf() for this map");
  cv::Mat sum;
  cv::integral(region, sum, CV_32S);
  return sum;
}

std::vector<double> CorrelativeMatcher::wallAlignedHeadings(const mrpt::obs::CObservation2DRangeScan& scan,
                                                            const MatchRequest& request) const {
  if (!(request.wall_heading_window_deg > 0.0) || map_axes_.support < params_.min_wall_support) return {};
  const WallAxes scan_axes = scanWallAxes(scan, params_.wall_axes);
  if (scan_axes.support < params_.min_wall_support) return {};
  return wallAlignedMapHeadings(scan_axes, map_axes_);
}

std::vector<CorrelativeMatcher::Rotation> CorrelativeMatcher::rotationsOf(const std::vector<mrpt::math::TPoint2D>& points,
                                                                          const mrpt::obs::CObservation2DRangeScan& scan,
                                                                          const MatchRequest& request) const {
  const auto centres = wallAlignedHeadings(scan, request);
  const double window = request.wall_heading_window_deg * M_PI / 180.0;
  const auto in_window = [&](double phi) {
    if (centres.empty()) return true;
    for (double c : centres)
      if (std::abs(mrpt::math::wrapToPi(phi - c)) <= window) return true;
    return false;
  };
  std::vector<Rotation> rotations;
  const int n_rot = std::max(1, static_cast<int>(std::lround(360.0 / params_.angular_step_deg)));
  for (int k = 0; k < n_rot; ++k) {
    const double phi = -M_PI + 2.0 * M_PI * k / n_rot;
    if (in_window(phi)) rotations.push_back(rotate(points, phi));
  }
  return rotations;
}

void CorrelativeMatcher::countAfresh() const {
  nodes_scored_ = 0;
  nodes_stopped_early_ = 0;
  cut_short_ = false;
}

bool CorrelativeMatcher::isCandidate(int cx, int cy, const cv::Mat& region_sum,
                                     const std::vector<mrpt::math::TPoint2D>& excluded) const {
  if (cx >= free_.cols || cy >= free_.rows || !robotCellFree(cx, cy) || !windowHoldsRegion(region_sum, cx, cy, 0))
    return false;
  const auto at = poseOf(cx, cy, 0.0);
  for (const auto& p : excluded)
    if (std::hypot(p.x - at.x, p.y - at.y) < params_.exclusion_m) return false;
  return true;
}

}  // namespace krp
