// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/place_tracker.h"

#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/rival_test.h"
#include "mrpt_krp_plugin/filter/sensor_model.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "support/test_maps.h"

namespace krp {
namespace {

using mrpt::math::TPose2D;

// A short drive in the asymmetric room (the default one, and the first of the twin rooms).
std::vector<TPose2D> drive() {
  std::vector<TPose2D> path;
  for (int i = 0; i < 6; ++i) path.emplace_back(5.2 + 0.2 * i, 2.2, 0.3 + 0.05 * i);
  return path;
}

/// The 180 deg twin of `p` in the default asymmetric room: most walls agree, the L wall does not.
TPose2D twinOf(const TPose2D& p) { return {9.0 - p.x, 7.0 - p.y, mrpt::math::wrapToPi(p.phi + M_PI)}; }

double distance(const TPose2D& a, const TPose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

mrpt::maps::COccupancyGridMap2D asTheFilterSeesIt(mrpt::maps::COccupancyGridMap2D map) {
  useSensorModel(map, SensorModelParams{});
  return map;
}

/// What decides between two places: the rival test's bar.
const double kDecisive = RivalTestParams{}.decisive_log_ratio;

/// Starts `tracker` with `places` on the path's first scan and drives the rest of it, moving
/// every place by the path's own odometry.
void driveTracker(PlaceTracker& tracker, const mrpt::maps::COccupancyGridMap2D& world,
                  const std::vector<TPose2D>& path, const std::vector<TPose2D>& places) {
  Rng rng(7);
  const ScanSimulator lidar(lidarProfileByName("omni_12m"));
  for (size_t i = 0; i < path.size(); ++i) {
    const auto scan = lidar.simulate(world, mrpt::poses::CPose2D(path[i]), rng);
    if (i == 0) {
      tracker.start(world, *scan, places, nullptr);
    } else {
      tracker.move(mrpt::poses::CPose2D(path[i]) - mrpt::poses::CPose2D(path[i - 1]));
      tracker.update(world, *scan, nullptr);
    }
  }
}

TEST(PlaceTracker, ThePathDecidesForThePlaceTheScansWereTakenAt) {
  const auto room = asTheFilterSeesIt(test::asymmetricRoom());
  const auto path = drive();
  PlaceTracker tracker;
  // The twin first, a few centimetres off the truth second: both are placed, then weighed.
  const TPose2D near_truth(path[0].x + 0.05, path[0].y - 0.05, path[0].phi + 0.02);
  driveTracker(tracker, room, path, {twinOf(path[0]), near_truth});
  ASSERT_EQ(tracker.places().size(), 2u) << "places are kept, in their order";
  const auto& twin = tracker.places()[0];
  const auto& truth = tracker.places()[1];
  EXPECT_LT(distance(truth.pose, path.back()), 0.05) << "the place near the truth followed the robot";
  EXPECT_GE(truth.log_likelihood - twin.log_likelihood, kDecisive);
}

TEST(PlaceTracker, TwinRoomsStayUndecided) {
  const auto rooms = asTheFilterSeesIt(test::twinRooms());
  const auto path = drive();
  const double shift = test::twinRoomsShiftM();
  PlaceTracker tracker;
  driveTracker(tracker, rooms, path, {path[0], {path[0].x + shift, path[0].y, path[0].phi}});
  ASSERT_EQ(tracker.places().size(), 2u);
  EXPECT_LT(std::abs(tracker.places()[0].log_likelihood - tracker.places()[1].log_likelihood), kDecisive)
      << "both rooms explain the path";
}

// Started a quarter step off its pose in x, y and heading (a pose rounded to the matcher's
// grid is off by that much on average), a place held on the coarse grid stays that far off
// and pays for it on every scan; the finer grids take it to its best.
TEST(PlaceTracker, FinerRefinementsRecoverWhatTheCoarseGridLoses) {
  const auto room = asTheFilterSeesIt(test::asymmetricRoom());
  const auto path = drive();
  PlaceTrackerParams coarse;
  coarse.first_scan_search_m = coarse.first_scan_search_deg = 0.0;
  coarse.finer_refinements = 0;
  auto fine = coarse;
  fine.finer_refinements = PlaceTrackerParams{}.finer_refinements;
  const TPose2D off(path[0].x + 0.0125, path[0].y + 0.0125, path[0].phi + 0.25 * M_PI / 180.0);
  PlaceTracker exact(fine), held(coarse), refined(fine);
  driveTracker(exact, room, path, {path[0]});
  driveTracker(held, room, path, {off});
  driveTracker(refined, room, path, {off});
  const double per_scan = 1.0 / static_cast<double>(path.size());
  const double exact_ll = exact.places().front().log_likelihood;
  const double lost_held = (exact_ll - held.places().front().log_likelihood) * per_scan;
  const double lost_refined = (exact_ll - refined.places().front().log_likelihood) * per_scan;
  EXPECT_GT(lost_held, 0.3) << "nats a scan lost on the coarse grid";
  EXPECT_LT(std::abs(lost_refined), 0.25 * lost_held) << "lost on the coarse grid " << lost_held << ", refined " << lost_refined;
}

TEST(PlaceTracker, RefusesNegativeStepsAndRefinements) {
  PlaceTrackerParams p;
  p.refine_step_m = -0.01;
  EXPECT_THROW(PlaceTracker{p}, std::invalid_argument);
  p = {};
  p.first_scan_search_deg = -1.0;
  EXPECT_THROW(PlaceTracker{p}, std::invalid_argument);
  p = {};
  p.finer_refinements = -1;
  EXPECT_THROW(PlaceTracker{p}, std::invalid_argument);
}

}  // namespace
}  // namespace krp
