// SPDX-License-Identifier: BSD-3-Clause
#include "support/seeded_drives.h"

#include <cmath>

#include "support/test_maps.h"

namespace krp::test {

PoseHypothesis hypothesisAt(const mrpt::math::TPose2D& pose, double confidence) {
  PoseHypothesis h;
  h.pose = pose;
  h.cov.setZero();
  h.cov(0, 0) = h.cov(1, 1) = 0.3 * 0.3;
  h.cov(2, 2) = std::pow(5.0 * M_PI / 180.0, 2);
  h.confidence = confidence;
  return h;
}

namespace {
TrialParams eightSteps() {
  TrialParams tp;
  tp.steps = 8;
  return tp;
}
}  // namespace

RoomTrial::RoomTrial()
    : room(std::make_shared<const mrpt::maps::COccupancyGridMap2D>(asymmetricRoom())),
      trial(generateTrial(*room, lidarProfileByName("omni_12m"), eightSteps(), 2)),
      steps(trialToSteps(trial)) {}

}  // namespace krp::test
