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

  /// Odometry pose and its time [s].
  struct Sample {
    double time_s;
    mrpt::math::TPose2D pose;
  };

  /// The poses `samples` gives, in any order; of two with one time, the first is kept. Throws
  /// std::invalid_argument for a max_gap_s that is negative or not finite.
  explicit OdometryTimeline(std::vector<Sample> samples = {}, double max_gap_s = kDefaultMaxGapS);

  std::size_t size() const { return samples_.size(); }  ///< poses kept (one per time)

  /// The odometry at `time_s`: interpolated between the poses around it (heading along the
  /// shorter turn), or the nearer end's pose outside them; none when the nearest pose is more
  /// than max_gap_s away.
  std::optional<mrpt::math::TPose2D> at(double time_s) const;

 private:
  double max_gap_s_;
  std::vector<Sample> samples_;  ///< by time
};

}  // namespace krp
