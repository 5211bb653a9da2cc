// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/submap/wall_axes.h"
#include "mrpt_krp_plugin/zones/zone.h"

namespace krp {

struct CorrelativeMatcherParams {
  double resolution_m = 0.1;       ///< search grid cell; the map is resampled to it [m]
  double angular_step_deg = 1.0;   ///< heading step of the exhaustive search [deg]
  double hit_sigma_m = 0.1;        ///< a return scores exp(-d^2 / 2 sigma^2) at distance d from an obstacle [m]
  int depth = 6;                   ///< branch-and-bound levels: the coarsest node covers 2^depth cells a side
  int max_points = 180;            ///< returns used, evenly decimated
  double min_score = 0.4;          ///< solutions scoring below this are not reported [0..1]
  int solutions = 2;               ///< best, then the best at least `exclusion_m` from every earlier one
  double exclusion_m = 1.0;        ///< [m]
  double min_occupancy = 0.65;     ///< map cells above this are obstacles [0..1]
  double min_freeness = 0.6;       ///< the robot's own cell must be at least this free [0..1]
  /// The score grids extend this far beyond the map on every side (scoring nothing there), so
  /// that a scan whose returns reach no farther outside is bounded without edge checks. Costs
  /// memory: (width + 2 margin) x (height + 2 margin) x (depth + 1) floats [m].
  double margin_m = 15.0;
  /// A node's bound stops reading returns once it cannot beat what the search must beat (no
  /// return scores above 1). The answers and the nodes scored are the same either way; false
  /// reads every return, for the side-by-side benchmark (krp-bench-matcher).
  bool stop_bound_early = true;
  /// A search for several solutions starts each one after the first from the best candidate an
  /// earlier one passed on its way that may still be a solution, instead of from min_score: it
  /// prunes from that score on. The answers' scores are the same either way; their poses too but
  /// where two places score exactly alike. false starts each from min_score, for the side-by-side
  /// benchmark (krp-bench-matcher).
  bool warm_start_later_solutions = true;
  /// The depth-first search visits the coarsest nodes of every heading in one order, highest
  /// bound first, instead of heading after heading: the best place tends to be reached sooner,
  /// and from then on it prunes the other headings. The answers' scores are the same either way;
  /// their poses too but where two places score exactly alike. false goes heading after heading,
  /// for the side-by-side benchmark (krp-bench-matcher).
  bool roots_across_headings = true;
  /// How the map's and a scan's wall directions are measured, for a request's
  /// wall_heading_window_deg.
  WallAxesParams wall_axes;
  /// A request's wall_heading_window_deg narrows the headings only when at least this share of
  /// the wall length of the map and of the scan lies along their dominant direction
  /// (WallAxes::support): a map with walls at several angles, or a scan of clutter, keeps every
  /// heading [0..1].
  double min_wall_support = 0.5;
};

/// What one match() looks for; every field left empty keeps the parameters' choice.
struct MatchRequest {
  cv::Mat region;  ///< from regionOf(): only poses inside it; empty = the whole map
  /// Replaces CorrelativeMatcherParams::min_score: a high one (what a known pose already scores)
  /// prunes most of the search, which is what makes checking an answer for look-alikes cheap.
  std::optional<double> min_score;
  std::optional<int> solutions;                  ///< replaces CorrelativeMatcherParams::solutions
  std::vector<mrpt::math::TPoint2D> excluded;    ///< no solution within exclusion_m of these
  /// Evidence the returns' endpoints cannot show (a return from beyond a mapped wall), charged
  /// to each full-resolution candidate in score units: a solution's score is its endpoint score
  /// less this. It must never be negative, so that the coarser levels' bounds still bound every
  /// candidate and the search stays exact. `enough` is the charge that takes the candidate down
  /// to min_score: the function may stop there and return any value at least as large. With
  /// it the search runs best-first, so that only candidates whose endpoint score beats the
  /// answer are charged. Empty: none.
  std::function<double(const mrpt::math::TPose2D& pose, double enough)> leaf_penalty;
  /// With leaf_penalty: one solution's search scores at most this many nodes (a scan whose
  /// endpoints fit many places, as among a warehouse's racks, leaves many bounds above the
  /// answer, and the search can cost seconds); then the best candidate charged so far is the
  /// answer, which may not be the best there is (lastSearchCutShort() says so). 0: no limit, the
  /// search is exact. Without leaf_penalty the depth-first search is exact and ignores this.
  long long max_nodes_scored = 0;
  /// Above 0: only headings within this of one at which the scan's walls lie along the map's
  /// (wallAlignedMapHeadings), when both have a clear wall direction (min_wall_support); else
  /// every heading. Where walls meet at right angles, a place the scan fits has its walls along
  /// the map's, and four narrow windows replace the full turn [deg]. 0: every heading.
  double wall_heading_window_deg = 0.0;
  /// Windows of 45 deg around four headings 90 deg apart already cover every heading.
  static constexpr double kMaxWallHeadingWindowDeg = 45.0;
  /// Whether `deg` is a wall_heading_window_deg one can ask for: 0 to kMaxWallHeadingWindowDeg.
  static bool validWallHeadingWindow(double deg) { return deg >= 0.0 && deg <= kMaxWallHeadingWindowDeg; }
  /// What validWallHeadingWindow accepts, in words, for the messages that refuse a setting.
  static std::string wallHeadingWindowRange() {
    return "0 (every heading) to " + std::to_string(static_cast<int>(kMaxWallHeadingWindowDeg));
  }

  /// Only poses inside `region`, everything else as the parameters say.
  static MatchRequest within(const cv::Mat& region) {
    MatchRequest r;
    r.region = region;
    return r;
  }
};

struct MatchSolution {
  mrpt::math::TPose2D pose;  ///< robot pose in the map frame, on the search grid
  double score = 0.0;        ///< mean return score, less the request's leaf_penalty [0..1]
};

/// The global scan matcher a user would otherwise reach for: an exhaustive multi-resolution
/// correlative search over every free cell and heading of the map, made exact and fast by
/// branch and bound (as Cartographer's global localization does). Its second solution, found
/// away from the first, says how ambiguous the scan is.
class CorrelativeMatcher {
 public:
  class Search;

  CorrelativeMatcher(const mrpt::maps::COccupancyGridMap2D& map, CorrelativeMatcherParams params = {});

  /// The search grid's cells inside any of `zones` (CV_8U, 1 = searched): a region for match().
  cv::Mat regionOf(const std::vector<Zone>& zones) const;

  /// Best first; empty when nothing scores min_score. With a region, whole branches outside it
  /// are skipped unscored.
  std::vector<MatchSolution> match(const mrpt::obs::CObservation2DRangeScan& scan, const MatchRequest& request = {}) const;

  /// The centres of the heading windows to which `request` narrows the search for `scan` (its
  /// wall_heading_window_deg, where the map's and the scan's wall directions are clear); empty
  /// when every heading is searched.
  std::vector<double> wallAlignedHeadings(const mrpt::obs::CObservation2DRangeScan& scan, const MatchRequest& request) const;

  /// The score match() gives `pose` (same returns, same grid), without searching: how well the
  /// scan fits there in the matcher's own units.
  double scoreAt(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose) const;

  /// A match() for one solution with a leaf_penalty, set up but not run: resume() runs it in
  /// slices, so that a caller that must keep up with its scans (the filter's look-alike guard)
  /// can spread a search that costs seconds over several of them. It keeps copies of what it
  /// needs of `scan` and `request`; what `request.leaf_penalty` refers to must outlive it. Throws
  /// std::invalid_argument without a leaf_penalty or with more than one solution asked.
  std::unique_ptr<Search> startSearch(const mrpt::obs::CObservation2DRangeScan& scan, const MatchRequest& request) const;
  /// Goes on with `search` for about `max_nodes` more nodes (0: to its end; its first slice
  /// also bounds every root, and a slice ends within one node's children of the number); true
  /// once it has finished. Sliced or not, a search scores the same nodes in the same order and
  /// ends with the same answer, its request's max_nodes_scored counting every slice.
  bool resume(Search& search, long long max_nodes) const;

  /// Nodes whose bound was computed in the last match(), or by the search last begun with
  /// startSearch() and its resume()s so far (a measure of its cost).
  long long lastNodesScored() const { return nodes_scored_; }
  /// Of those, the ones whose bound stopped early (CorrelativeMatcherParams::stop_bound_early).
  long long lastNodesStoppedEarly() const { return nodes_stopped_early_; }
  /// The last match() (or that search) ran out of MatchRequest::max_nodes_scored: its answer may
  /// not be the best.
  bool lastSearchCutShort() const { return cut_short_; }
  const CorrelativeMatcherParams& params() const { return params_; }

 private:
  /// Starts the last-search counters (lastNodesScored and the rest) at zero.
  void countAfresh() const;
  /// startSearch() without starting the counters afresh, so match() counts all its searches.
  std::unique_ptr<Search> setUpSearch(const mrpt::obs::CObservation2DRangeScan& scan, const MatchRequest& request) const;

  static constexpr double kNoCutoff = -std::numeric_limits<double>::infinity();
  static constexpr double kPruned = -std::numeric_limits<double>::infinity();
  /// Returns gathered between two checks against the cutoff (a multiple of 4, the running sums).
  static constexpr size_t kCutoffCheckEvery = 16;
  /// Checkpoints kept per node (returns past the last are read without checks).
  static constexpr size_t kMaxCheckpoints = 64;
  struct Rotation {
    double phi;
    std::vector<cv::Point> offsets;  ///< each return's cell offset from the robot's cell
    /// The same offsets as indices into a row-major level grid, and their bounding box: a node
    /// whose returns all land inside the grid is bounded by a plain gather, without per-return
    /// edge checks (the bound is where the search spends its time).
    std::vector<int> linear;
    int min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  };
  struct Node {
    int cx, cy, level;
    double bound;  ///< no candidate in the node's window scores more
    /// Where the node's tail sums start in the search's TailSums (-1: none kept). A child's window
    /// lies inside its parent's, so on every return it scores at most what the parent does, and
    /// the parent's sum over the returns not yet read bounds the child's far tighter than one per
    /// return: the child's bound can stop after far fewer returns.
    std::int64_t tail = -1;
  };
  /// Tail sums of the nodes a search keeps: at each checkpoint, the node's sum over the returns
  /// after it (rounded up to float, so still a bound).
  using TailSums = std::vector<float>;
  using InRegion = std::function<bool(int cx, int cy, int level)>;
  using Candidate = std::function<bool(int cx, int cy)>;  ///< a cell a solution may stand on

  /// The coarsest nodes over the search grid that hold any of the region, bounded for `rot`
  /// (those that cannot beat `cutoff` marked kPruned).
  std::vector<Node> roots(const Rotation& rot, const InRegion& in_region, double cutoff, TailSums& tails) const;
  /// `n`'s children (up to four) inside the grid and the region, bounded for `rot` as roots()
  /// does, written to `out`; how many.
  size_t children(const Rotation& rot, const Node& n, const TailSums& n_tails, const InRegion& in_region, double cutoff,
                  TailSums& tails, std::array<Node, 4>& out) const;
  /// A candidate a depth-first search took as its best at some point, with its cell.
  struct Improvement {
    MatchSolution solution;
    int cx, cy;
  };
  /// The best candidate scoring above `bar`: depth-first, best child first, pruned by the best
  /// found so far (fast when nothing is charged beyond the endpoint score). `start`: a candidate
  /// known to score above `bar`, the best until a better one is found, so that the search prunes
  /// from its score on. Every candidate taken as the best is appended to `improvements` (if given).
  std::optional<MatchSolution> searchDepthFirst(const std::vector<Rotation>& rotations, double bar,
                                                const InRegion& in_region, const Candidate& candidate,
                                                const std::optional<MatchSolution>& start = std::nullopt,
                                                std::vector<Improvement>* improvements = nullptr) const;
  /// A cell a solution may stand on: free, in the region (regionSum's; empty: anywhere) and at
  /// least exclusion_m from each of `excluded`.
  bool isCandidate(int cx, int cy, const cv::Mat& region_sum, const std::vector<mrpt::math::TPoint2D>& excluded) const;
  /// The integral image of a region from regionOf() (empty for none); throws
  /// std::invalid_argument for one made for another map.
  cv::Mat regionSum(const cv::Mat& region) const;
  /// Whether a node's window (level `level` at cx, cy) holds any of the region, in O(1).
  static bool windowHoldsRegion(const cv::Mat& region_sum, int cx, int cy, int level);
  /// The returns turned to every heading of the search (angular_step_deg apart), or to those the
  /// request's wall_heading_window_deg leaves.
  std::vector<Rotation> rotationsOf(const std::vector<mrpt::math::TPoint2D>& points,
                                    const mrpt::obs::CObservation2DRangeScan& scan, const MatchRequest& request) const;
  mrpt::math::TPose2D poseOf(int cx, int cy, double phi) const;  ///< a search-grid cell's centre, heading phi
  /// The scan's returns in the robot frame, evenly decimated to max_points.
  std::vector<mrpt::math::TPoint2D> returns(const mrpt::obs::CObservation2DRangeScan& scan) const;
  Rotation rotate(const std::vector<mrpt::math::TPoint2D>& points, double phi) const;
  /// The node's bound: no candidate in its window scores more. When it cannot exceed `cutoff`,
  /// kPruned instead (found without reading every return; the caller drops the node either way).
  /// `parent_tail`: the tail sums of a node whose window holds this one's (null: none). With
  /// `tail_out` (checkpoints(r) floats), the node's own tail sums are written there unless pruned.
  double bound(const Rotation& r, int cx, int cy, int level, double cutoff = kNoCutoff,
               const float* parent_tail = nullptr, float* tail_out = nullptr) const;
  /// One node's bound() being gathered (the nodes whose returns all land inside the level grid).
  struct BoundLane {
    const float* robot_cell = nullptr;  ///< the node's cell in its level grid
    float* tail_out = nullptr;          ///< its tail sums, or null
    double part[4] = {0, 0, 0, 0};      ///< four running sums: one would make each addition wait for the last
    std::array<double, kMaxCheckpoints> read_by;  ///< the sum at each checkpoint, written before any read
  };
  /// Whether the node's returns all land inside its level grid (bound()'s plain gather).
  bool gathersInside(const Rotation& r, int cx, int cy, int level) const;
  /// The node's cell in the level grid of `level`.
  const float* robotCell(int cx, int cy, int level) const {
    return levels_[level].ptr<float>(cy + margin_) + cx + margin_;
  }
  /// bound()'s gather of `lane` from checkpoint `k` on (k * kCutoffCheckEvery returns read).
  double gatherFrom(const Rotation& r, BoundLane& lane, size_t k, double cutoff, const float* parent_tail) const;
  /// bound() of two nodes of one level whose returns land inside the grid, gathered side by side
  /// so that each sum's wait for its last addition overlaps the other node's (each node's sums
  /// are added in bound()'s order: the same bounds, bit for bit); each return's offset is read once.
  void boundPair(const Rotation& r, BoundLane (&lanes)[2], double cutoff, const float* parent_tail, double (&out)[2]) const;
  /// The bounds of `count` nodes of one level (bound() with `cutoff` and `parent_tail`), pairs of
  /// them side by side, each node's tail sums appended to `tails` unless it is pruned, in order.
  void boundNodes(const Rotation& r, Node* nodes, size_t count, double cutoff, const float* parent_tail,
                  TailSums& tails) const;
  /// Checkpoints of a bound over `r`'s returns (one every kCutoffCheckEvery returns, at most kMaxCheckpoints).
  static size_t checkpoints(const Rotation& r) { return std::min(r.linear.size() / kCutoffCheckEvery, kMaxCheckpoints); }
  /// A new node's tail sums go to the end of `tails`: where they start, and room for them.
  static float* reserveTail(const Rotation& r, TailSums& tails, std::int64_t* start);
  /// Margin on the cutoff test, far above the rounding of a sum of a few hundred scores in [0, 1].
  static constexpr double kCutoffSlack = 1e-9;
  bool robotCellFree(int cx, int cy) const { return free_.at<uint8_t>(cy, cx) != 0; }

  CorrelativeMatcherParams params_;
  /// levels_[h](y, x): max of the score grid over [x, x + 2^h) x [y, y + 2^h), in cells of the
  /// search grid shifted by margin_ (map cell (cx, cy) is levels_[h](cy + margin_, cx + margin_)).
  std::vector<cv::Mat> levels_;
  int margin_ = 0;               ///< margin_m in cells
  cv::Mat free_;                 ///< CV_8U, robot may stand here
  WallAxes map_axes_;            ///< the map's wall direction, for wall_heading_window_deg
  double x_min_ = 0, y_min_ = 0;
  mutable long long nodes_scored_ = 0;
  mutable long long nodes_stopped_early_ = 0;
  mutable bool cut_short_ = false;
};

/// One solution's best-first search, every candidate charged the request's leaf_penalty: the
/// highest bound is expanded first, and a candidate is charged only when it reaches the top, then
/// queued again with its charge, so a charged candidate at the top beats every bound left.
/// Made by CorrelativeMatcher::startSearch, run by its resume().
class CorrelativeMatcher::Search {
 public:
  bool finished() const { return finished_; }
  /// Once finished: the best candidate scoring above the request's bar, if any.
  const std::optional<MatchSolution>& solution() const { return solution_; }
  /// It ended by running out of the request's max_nodes_scored: solution() is the best
  /// candidate charged by then, a true answer but maybe not the best there is.
  bool cutShort() const { return cut_short_; }
  long long nodesScored() const { return nodes_; }  ///< over every slice so far

 private:
  friend class CorrelativeMatcher;
  struct Entry {
    double key;  ///< bound, or a charged candidate's score
    int rotation;
    Node node;
    bool charged;
    bool operator<(const Entry& o) const { return key < o.key; }
  };
  double floor() const { return best_ ? best_->key : bar_; }  ///< what a node must beat

  MatchRequest request_;
  cv::Mat region_sum_;  ///< the region's integral image: region cells in any window in O(1)
  std::vector<Rotation> rotations_;
  double bar_ = 0.0;
  std::priority_queue<Entry> queue_;
  std::optional<Entry> best_;  ///< the best charged candidate so far
  TailSums tails_;             ///< of every node queued, for its children's bounds
  long long nodes_ = 0;
  bool rooted_ = false, finished_ = false, cut_short_ = false;
  std::optional<MatchSolution> solution_;
};

}  // namespace krp
