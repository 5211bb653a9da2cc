// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/TPose2D.h>

#include <optional>
#include <vector>

namespace krp {

/// A log's odometry poses by time (CARMEN ODOM lines), asked for the pose at another line's time:
/// a RAWLASER line carries no pose of its own, so its scan takes the odometry of its instant.
class OdometryTimeline {
 public:
  /// A pose may be taken from odometry at most this far in time from the instant asked [s]: the
  /// nearest ODOM line beyond it says nothing about where the robot was then.
  static constexpr double kDefaultMaxGapS = 0.5;

  explicit OdometryTimeline(double max_gap_s = kDefaultMaxGapS);

  /// Adds the odometry pose at `time_s`. Any order; a time already given keeps its first pose.
  void add(double time_s, const mrpt::math::TPose2D& pose);
  std::size_t size() const { return samples_.size(); }  ///< poses added (a repeated time counted until asked)

  /// The odometry at `time_s`: interpolated between the poses around it (heading along the
  /// shorter turn), or the nearer end's pose outside them; none when the nearest pose is more
  /// than max_gap_s away.
  std::optional<mrpt::math::TPose2D> at(double time_s) const;

 private:
  struct Sample {
    double time_s;
    mrpt::math::TPose2D pose;
  };
  double max_gap_s_;
  mutable std::vector<Sample> samples_;
  mutable bool sorted_ = true;
};

}  // namespace krp
