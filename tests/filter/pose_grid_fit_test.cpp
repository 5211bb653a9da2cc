// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/pose_grid_fit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/sensor_model.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "support/test_maps.h"

namespace krp {
namespace {

using mrpt::math::TPose2D;

const TPose2D kTruth(5.52, 2.07, 0.8);
// A quarter of the default grid's steps off in x, y and heading: where a pose rounded to a
// 5 cm / 1 deg grid sits on average.
const TPose2D kOff(kTruth.x + 0.0125, kTruth.y - 0.0125, kTruth.phi + 0.25 * M_PI / 180.0);

struct Scene {
  mrpt::maps::COccupancyGridMap2D room = test::asymmetricRoom();
  mrpt::obs::CObservation2DRangeScan::Ptr scan;
  Scene() {
    useSensorModel(room, SensorModelParams{});
    Rng rng(11);
    scan = ScanSimulator(lidarProfileByName("omni_12m")).simulate(room, mrpt::poses::CPose2D(kTruth), rng);
  }
};

TEST(PoseGridFit, NoRefinementIsTheFirstGridAlone) {
  const Scene s;
  const PoseGrid grid;
  const auto once = bestPoseOnGrid(s.room, *s.scan, kOff, grid);
  const auto refined = refinedPoseOnGrids(s.room, *s.scan, kOff, grid, 0);
  EXPECT_DOUBLE_EQ(refined.score, once.score);
  EXPECT_DOUBLE_EQ(refined.pose.x, once.pose.x);
  EXPECT_DOUBLE_EQ(refined.pose.phi, once.pose.phi);
}

// Each finer grid holds its centre, the last grid's best, so the fit never gets worse; from a
// quarter step off, the finer grids take the pose closer to where the scan was taken than the
// first grid can (it only moves in whole steps).
TEST(PoseGridFit, FinerGridsTakeThePoseCloserToItsBest) {
  const Scene s;
  const PoseGrid grid;
  double last_score = -1e300;
  PoseGridFit fit;
  for (int refinements = 0; refinements <= 3; ++refinements) {
    fit = refinedPoseOnGrids(s.room, *s.scan, kOff, grid, refinements);
    EXPECT_GE(fit.score, last_score) << refinements << " refinements";
    last_score = fit.score;
  }
  const auto coarse = refinedPoseOnGrids(s.room, *s.scan, kOff, grid, 0);
  EXPECT_GT(fit.score - coarse.score, 0.3) << "nats the finer grids recover on one scan";
  const double off_m = std::hypot(fit.pose.x - kTruth.x, fit.pose.y - kTruth.y);
  EXPECT_LT(off_m, std::hypot(kOff.x - kTruth.x, kOff.y - kTruth.y)) << "closer to the truth than it started";
}

}  // namespace
}  // namespace krp
