// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <deque>
#include <optional>

#include "mrpt_krp_plugin/filter/rival_test.h"
#include "mrpt_krp_plugin/filter/see_through.h"

namespace krp {

/// The last few updates' scans and odometry, so that a look-alike found now can be weighed over
/// the path already driven. A look-alike found on one scan starts its test even with the
/// tracked pose, and the scans that follow may see only more of the same aisle; yet a twin robot
/// standing there now would have driven the same odometry from a place as far back, and the
/// scans already taken can tell the two paths apart.
class ScanHistory {
 public:
  /// Keeps the `capacity` latest updates (0: keeps none, and primedTest is a plain RivalTest).
  explicit ScanHistory(std::size_t capacity = 0) : capacity_(capacity) {}

  /// One update: its scan, the scan's see-through penalty when the filter charges one, and the
  /// odometry increment from the update before to this one.
  /// With capacity 0 nothing is copied: the filter calls this on every update.
  void push(const mrpt::obs::CObservation2DRangeScan& scan, const std::optional<SeeThroughPenalty::Scan>& see_through,
            const mrpt::poses::CPose2D& increment);
  void clear() { steps_.clear(); }
  std::size_t size() const { return steps_.size(); }
  std::size_t capacity() const { return capacity_; }

  /// A test of `rival` against `tracked` (both where they stand now) that has weighed every stored
  /// scan: each side is moved back by the odometry (the stored increments, and `since_newest`, the
  /// motion since the newest stored update) to where it stood at the oldest, then driven forward
  /// scan by scan as RivalTest does. The current scan is not counted: the caller adds it.
  RivalTest primedTest(const mrpt::math::TPose2D& rival, const mrpt::math::TPose2D& tracked,
                       const mrpt::poses::CPose2D& since_newest, const mrpt::maps::COccupancyGridMap2D& map,
                       const RivalTestParams& params) const;

 private:
  struct Step {
    mrpt::obs::CObservation2DRangeScan scan;
    std::optional<SeeThroughPenalty::Scan> see_through;
    mrpt::poses::CPose2D increment;  ///< odometry from the update before this one
  };
  std::size_t capacity_;
  std::deque<Step> steps_;
};

}  // namespace krp
