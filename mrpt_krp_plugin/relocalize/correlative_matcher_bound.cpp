// SPDX-License-Identifier: BSD-3-Clause
// CorrelativeMatcher's node bounds: where a search spends its time.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"

namespace krp {

namespace {
/// `sum` as a float no smaller than it, so a stored tail sum still bounds.
float roundedUp(double sum) {
  float f = static_cast<float>(sum);
  if (static_cast<double>(f) < sum) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

/// A node's four running sums added up, always in this order, so that a bound read by one path
/// or another comes out the same to the last bit.
double total(const double (&part)[4]) { return (part[0] + part[1]) + (part[2] + part[3]); }

/// The end of a gather whose returns sum to `sum`: the node's tail sums, where it keeps them
/// (each checkpoint's sum of the returns after it), and its bound.
template <typename Lane>
double finishGather(Lane& lane, double sum, size_t returns, size_t checks) {
  if (lane.tail_out)
    for (size_t c = 0; c < checks; ++c) lane.tail_out[c] = roundedUp(sum - lane.read_by[c]);
  return sum / static_cast<double>(returns);
}
}  // namespace

bool CorrelativeMatcher::gathersInside(const Rotation& r, int cx, int cy, int level) const {
  const cv::Mat& g = levels_[level];
  const int gx = cx + margin_, gy = cy + margin_;
  return gx + r.min_x >= 0 && gy + r.min_y >= 0 && gx + r.max_x < g.cols && gy + r.max_y < g.rows;
}

double CorrelativeMatcher::bound(const Rotation& r, int cx, int cy, int level, double cutoff, const float* parent_tail,
                                 float* tail_out) const {
  ++nodes_scored_;
  if (!params_.stop_bound_early) tail_out = nullptr;
  if (gathersInside(r, cx, cy, level)) {
    BoundLane lane;
    lane.robot_cell = robotCell(cx, cy, level);
    lane.tail_out = tail_out;
    return gatherFrom(r, lane, 0, cutoff, parent_tail);
  }
  const cv::Mat& g = levels_[level];
  const int gx = cx + margin_, gy = cy + margin_;  // the node's cell in the level grids
  const size_t n = r.linear.size(), checks = checkpoints(r);
  double sum = 0;
  for (const auto& o : r.offsets) {
    const int x = gx + o.x, y = gy + o.y;
    // A node's window may start left of or below the grid: the part inside still bounds it.
    const int span = (1 << level) - 1;
    if (x + span < 0 || y + span < 0 || x >= g.cols || y >= g.rows) continue;
    sum += g.at<float>(std::max(y, 0), std::max(x, 0));
  }
  // Near the grid's edge only the plain bound of one per return is kept for the children.
  if (tail_out)
    for (size_t k = 0; k < checks; ++k) tail_out[k] = static_cast<float>(n - (k + 1) * kCutoffCheckEvery);
  return sum / static_cast<double>(r.offsets.size());
}

double CorrelativeMatcher::gatherFrom(const Rotation& r, BoundLane& lane, size_t k, double cutoff,
                                      const float* parent_tail) const {
  const size_t n = r.linear.size(), checks = checkpoints(r), whole = n - n % 4;
  const bool stop = params_.stop_bound_early && cutoff != kNoCutoff;
  const float* cell = lane.robot_cell;
  // Local, so that the sums stay in registers (a write to read_by could alias the lane's).
  double part[4] = {lane.part[0], lane.part[1], lane.part[2], lane.part[3]};
  size_t i = k * kCutoffCheckEvery;
  // The returns not read yet score at most one each, or at most the parent's over the same
  // returns: once the sum so far plus that cannot beat the cutoff, neither can the node, which
  // is pruned without reading the rest (most nodes of a search with a high bar end here). The
  // slack makes rounding (of the sums, of a parent's tail sums) err towards reading on, never
  // towards pruning a node the full bound would keep.
  if (stop || lane.tail_out) {
    const double needed = cutoff * static_cast<double>(n) - kCutoffSlack;
    for (; k < checks; ++k) {
      for (const size_t end = i + kCutoffCheckEvery; i < end; i += 4)
        for (size_t j = 0; j < 4; ++j) part[j] += cell[r.linear[i + j]];
      lane.read_by[k] = total(part);
      const double unread = parent_tail ? static_cast<double>(parent_tail[k]) : static_cast<double>(n - i);
      if (stop && lane.read_by[k] + unread < needed) {
        ++nodes_stopped_early_;
        return kPruned;
      }
    }
  }
  for (; i < whole; i += 4)
    for (size_t j = 0; j < 4; ++j) part[j] += cell[r.linear[i + j]];
  for (; i < n; ++i) part[0] += cell[r.linear[i]];
  return finishGather(lane, total(part), n, checks);
}

void CorrelativeMatcher::boundPair(const Rotation& r, BoundLane (&lanes)[2], double cutoff, const float* parent_tail,
                                   double (&out)[2]) const {
  nodes_scored_ += 2;
  const size_t n = r.linear.size(), checks = checkpoints(r), whole = n - n % 4;
  const bool stop = params_.stop_bound_early && cutoff != kNoCutoff;
  const float* a_cell = lanes[0].robot_cell;
  const float* b_cell = lanes[1].robot_cell;
  // Local, so that the sums stay in registers (the lanes' read_by could alias their sums).
  double a_part[4] = {0, 0, 0, 0}, b_part[4] = {0, 0, 0, 0};
  size_t i = 0;
  // Both nodes are of one level, so both keep tail sums or neither does.
  if (stop || lanes[0].tail_out) {
    const double needed = cutoff * static_cast<double>(n) - kCutoffSlack;
    for (size_t k = 0; k < checks; ++k) {
      for (const size_t end = i + kCutoffCheckEvery; i < end; i += 4)
        for (size_t j = 0; j < 4; ++j) {
          const int offset = r.linear[i + j];
          a_part[j] += a_cell[offset];
          b_part[j] += b_cell[offset];
        }
      const double a_read = total(a_part), b_read = total(b_part);
      lanes[0].read_by[k] = a_read;
      lanes[1].read_by[k] = b_read;
      const double unread = parent_tail ? static_cast<double>(parent_tail[k]) : static_cast<double>(n - i);
      const bool a_pruned = stop && a_read + unread < needed;
      const bool b_pruned = stop && b_read + unread < needed;
      if (a_pruned || b_pruned) {
        std::copy_n(a_part, 4, lanes[0].part);
        std::copy_n(b_part, 4, lanes[1].part);
        // The node left goes on alone from the next checkpoint, as bound() would have.
        for (int lane = 0; lane < 2; ++lane)
          if (lane == 0 ? a_pruned : b_pruned) {
            ++nodes_stopped_early_;
            out[lane] = kPruned;
          } else {
            out[lane] = gatherFrom(r, lanes[lane], k + 1, cutoff, parent_tail);
          }
        return;
      }
    }
  }
  for (; i < whole; i += 4)
    for (size_t j = 0; j < 4; ++j) {
      const int offset = r.linear[i + j];
      a_part[j] += a_cell[offset];
      b_part[j] += b_cell[offset];
    }
  for (; i < n; ++i) {
    a_part[0] += a_cell[r.linear[i]];
    b_part[0] += b_cell[r.linear[i]];
  }
  out[0] = finishGather(lanes[0], total(a_part), n, checks);
  out[1] = finishGather(lanes[1], total(b_part), n, checks);
}

void CorrelativeMatcher::boundNodes(const Rotation& r, Node* nodes, size_t count, double cutoff,
                                    const float* parent_tail, TailSums& tails) const {
  const bool keep_tails = count > 0 && nodes[0].level > 0;  // a level-0 node has no children to bound
  for (size_t i = 0; i < count;) {
    const bool pair = i + 1 < count && gathersInside(r, nodes[i].cx, nodes[i].cy, nodes[i].level) &&
                      gathersInside(r, nodes[i + 1].cx, nodes[i + 1].cy, nodes[i + 1].level);
    if (!pair) {
      Node& node = nodes[i++];
      float* tail = keep_tails ? reserveTail(r, tails, &node.tail) : nullptr;
      node.bound = bound(r, node.cx, node.cy, node.level, cutoff, parent_tail, tail);
      if (node.bound == kPruned && tail) {
        tails.resize(static_cast<size_t>(node.tail));  // a pruned node has no children to bound
        node.tail = -1;
      }
      continue;
    }
    Node& a = nodes[i];
    Node& b = nodes[i + 1];
    i += 2;
    BoundLane lanes[2];
    lanes[0].robot_cell = robotCell(a.cx, a.cy, a.level);
    lanes[1].robot_cell = robotCell(b.cx, b.cy, b.level);
    if (keep_tails) {
      // Reserved one after the other, then the pruned one's dropped: the layout bound() node by
      // node leaves (its tails, if any, are of the node that is kept).
      reserveTail(r, tails, &a.tail);
      reserveTail(r, tails, &b.tail);
      if (params_.stop_bound_early && a.tail >= 0) {
        lanes[0].tail_out = tails.data() + a.tail;
        lanes[1].tail_out = tails.data() + b.tail;
      }
    }
    double out[2];
    boundPair(r, lanes, cutoff, parent_tail, out);
    a.bound = out[0];
    b.bound = out[1];
    if (a.tail < 0) continue;  // no tails reserved
    const size_t checks = checkpoints(r);
    if (a.bound == kPruned && b.bound == kPruned) {
      tails.resize(static_cast<size_t>(a.tail));
      a.tail = b.tail = -1;
    } else if (a.bound == kPruned) {
      std::copy_n(tails.begin() + b.tail, checks, tails.begin() + a.tail);
      b.tail = a.tail;
      a.tail = -1;
      tails.resize(static_cast<size_t>(b.tail) + checks);
    } else if (b.bound == kPruned) {
      tails.resize(static_cast<size_t>(b.tail));
      b.tail = -1;
    }
  }
}

float* CorrelativeMatcher::reserveTail(const Rotation& r, TailSums& tails, std::int64_t* start) {
  const size_t checks = checkpoints(r);
  *start = -1;
  if (checks == 0) return nullptr;
  *start = static_cast<std::int64_t>(tails.size());
  tails.resize(tails.size() + checks);
  return tails.data() + *start;
}

}  // namespace krp
