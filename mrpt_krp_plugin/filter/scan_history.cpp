// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/scan_history.h"

namespace krp {

void ScanHistory::push(const mrpt::obs::CObservation2DRangeScan& scan,
                       const std::optional<SeeThroughPenalty::Scan>& see_through, const mrpt::poses::CPose2D& increment) {
  if (capacity_ == 0) return;
  steps_.push_back({scan, see_through, increment});
  while (steps_.size() > capacity_) steps_.pop_front();
}

RivalTest ScanHistory::primedTest(const mrpt::math::TPose2D& rival, const mrpt::math::TPose2D& tracked,
                                  const mrpt::poses::CPose2D& since_newest, const mrpt::maps::COccupancyGridMap2D& map,
                                  const RivalTestParams& params) const {
  if (steps_.empty()) return RivalTest(rival, params);
  // Back along the odometry: pose at update j = pose at j + 1 composed with the inverse of the
  // motion between them. Both sides are moved back alike.
  mrpt::poses::CPose2D rival_then(rival), tracked_then(tracked);
  const auto back = [](mrpt::poses::CPose2D& pose, const mrpt::poses::CPose2D& increment) { pose = pose + (-increment); };
  back(rival_then, since_newest);
  back(tracked_then, since_newest);
  for (std::size_t j = steps_.size() - 1; j > 0; --j) {
    back(rival_then, steps_[j].increment);
    back(tracked_then, steps_[j].increment);
  }
  RivalTest test(rival_then.asTPose(), params);
  for (std::size_t j = 0; j < steps_.size(); ++j) {
    if (j > 0) {
      test.move(steps_[j].increment);
      tracked_then = tracked_then + steps_[j].increment;
    }
    const auto& s = steps_[j];
    test.update(map, s.scan, tracked_then.asTPose(), s.see_through ? &*s.see_through : nullptr);
  }
  test.move(since_newest);
  return test;
}

}  // namespace krp
