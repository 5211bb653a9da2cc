// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/logs/odometry_timeline.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace krp {

OdometryTimeline::OdometryTimeline(std::vector<Sample> samples, double max_gap_s)
    : max_gap_s_(max_gap_s), samples_(std::move(samples)) {
  if (!(max_gap_s_ >= 0.0) || !std::isfinite(max_gap_s_))
    throw std::invalid_argument("OdometryTimeline: max_gap_s must be finite and >= 0");
  // Sorted once (stable, so that of two poses with one time the first stays first and is kept),
  // so that at() is a plain lookup.
  std::stable_sort(samples_.begin(), samples_.end(), [](const Sample& a, const Sample& b) { return a.time_s < b.time_s; });
  samples_.erase(std::unique(samples_.begin(), samples_.end(),
                             [](const Sample& a, const Sample& b) { return a.time_s == b.time_s; }),
                 samples_.end());
}

std::optional<mrpt::math::TPose2D> OdometryTimeline::at(double time_s) const {
  if (samples_.empty()) return std::nullopt;
  const auto after = std::lower_bound(samples_.begin(), samples_.end(), time_s,
                                      [](const Sample& s, double t) { return s.time_s < t; });
  if (after != samples_.end() && after->time_s == time_s) return after->pose;
  if (after == samples_.begin() || after == samples_.end()) {
    const Sample& end = after == samples_.end() ? samples_.back() : samples_.front();
    if (std::abs(end.time_s - time_s) > max_gap_s_) return std::nullopt;
    return end.pose;
  }
  const Sample& a = *std::prev(after);
  const Sample& b = *after;
  if (std::min(time_s - a.time_s, b.time_s - time_s) > max_gap_s_) return std::nullopt;
  const double s = (time_s - a.time_s) / (b.time_s - a.time_s);
  return mrpt::math::TPose2D(a.pose.x + s * (b.pose.x - a.pose.x), a.pose.y + s * (b.pose.y - a.pose.y),
                             mrpt::math::wrapToPi(a.pose.phi + s * mrpt::math::wrapToPi(b.pose.phi - a.pose.phi)));
}

}  // namespace krp
