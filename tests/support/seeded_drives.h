// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>

#include <memory>
#include <vector>

#include "mrpt_krp_plugin/relocalize/pose_hypothesis.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"
#include "mrpt_krp_plugin/sim/trial.h"

namespace krp::test {

/// What a stand-in for the relocalizer answers: `pose`, 0.3 m and 5 deg standard deviation, with
/// `confidence`.
PoseHypothesis hypothesisAt(const mrpt::math::TPose2D& pose, double confidence);

/// A short drive for the filter's system tests: 8 updates in the asymmetric room, 360 deg 12 m
/// lidar, trial seed 2.
struct RoomTrial {
  RoomTrial();
  std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> room;
  Trial trial;
  std::vector<RawlogStep> steps;
};

}  // namespace krp::test
