// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <stdexcept>
#include <tuple>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"
#include "mrpt_krp_plugin/sim/floor_plan.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "support/test_maps.h"

namespace krp {
namespace {

mrpt::obs::CObservation2DRangeScan::Ptr scanAt(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::poses::CPose2D& pose) {
  Rng rng(5);
  return ScanSimulator(lidarProfileByName("omni_12m")).simulate(map, pose, rng);
}

TEST(CorrelativeMatcher, FindsThePoseOverTheWholeMap) {
  const auto room = test::asymmetricRoom();
  const mrpt::poses::CPose2D truth(5.52, 2.07, 0.8);
  const CorrelativeMatcher matcher(room);
  const auto sols = matcher.match(*scanAt(room, truth));
  ASSERT_FALSE(sols.empty());
  EXPECT_NEAR(sols[0].pose.x, truth.x(), 0.1);
  EXPECT_NEAR(sols[0].pose.y, truth.y(), 0.1);
  // One search cell and a couple of heading steps: ICP refines from there.
  EXPECT_LT(std::abs(mrpt::math::wrapToPi(sols[0].pose.phi - truth.phi())), 2.5 * M_PI / 180.0);
  EXPECT_GT(sols[0].score, 0.7);
  // Its 180 deg twin explains most of the walls; only the L wall and the block tell them apart.
  if (sols.size() > 1) EXPECT_LT(sols[1].score, 0.9 * sols[0].score) << "the room has no symmetry";
}

TEST(CorrelativeMatcher, BranchAndBoundFindsWhatExhaustiveSearchFinds) {
  const auto room = test::asymmetricRoom();
  const auto scan = scanAt(room, mrpt::poses::CPose2D(2.0, 4.5, -2.2));
  CorrelativeMatcherParams exhaustive;
  exhaustive.angular_step_deg = 10.0;  // keeps the exhaustive run short
  exhaustive.depth = 0;
  exhaustive.solutions = 1;
  CorrelativeMatcherParams bnb = exhaustive;
  bnb.depth = 5;
  const CorrelativeMatcher a(room, exhaustive), b(room, bnb);
  const auto sa = a.match(*scan), sb = b.match(*scan);
  ASSERT_EQ(sa.size(), 1u);
  ASSERT_EQ(sb.size(), 1u);
  EXPECT_DOUBLE_EQ(sa[0].score, sb[0].score);
  EXPECT_DOUBLE_EQ(sa[0].pose.x, sb[0].pose.x);
  EXPECT_DOUBLE_EQ(sa[0].pose.y, sb[0].pose.y);
  EXPECT_LT(b.lastNodesScored(), a.lastNodesScored() / 5) << "the bounds should prune most of the search";
}

TEST(CorrelativeMatcher, ASymmetricRoomGivesTwoEqualSolutions) {
  FloorPlan plan(9.0, 7.0, 0.05);
  plan.building(0.5, 0.5, 8.5, 6.5);  // a bare rectangle: the pose and its 180 deg twin look alike
  const auto map = plan.toGrid();
  const CorrelativeMatcher matcher(map);
  const auto sols = matcher.match(*scanAt(map, mrpt::poses::CPose2D(3.0, 2.5, 0.3)));
  ASSERT_EQ(sols.size(), 2u);
  EXPECT_GT(sols[1].score, 0.95 * sols[0].score);
  const bool first_is_truth = std::hypot(sols[0].pose.x - 3.0, sols[0].pose.y - 2.5) < 0.2;
  const auto& twin = first_is_truth ? sols[1] : sols[0];
  EXPECT_NEAR(twin.pose.x, 9.0 - 3.0, 0.2);
  EXPECT_NEAR(twin.pose.y, 7.0 - 2.5, 0.2);
}

// A zone region decides between the twins: the search stays inside it and costs less.
TEST(CorrelativeMatcher, ARegionKeepsTheSearchInsideIt) {
  FloorPlan plan(9.0, 7.0, 0.05);
  plan.building(0.5, 0.5, 8.5, 6.5);
  const auto map = plan.toGrid();
  const CorrelativeMatcher matcher(map);
  const auto scan = scanAt(map, mrpt::poses::CPose2D(3.0, 2.5, 0.3));
  const auto whole = matcher.match(*scan);
  const long long whole_nodes = matcher.lastNodesScored();
  const Zone west{"west", {{0.0, 0.0}, {4.5, 0.0}, {4.5, 7.0}, {0.0, 7.0}}};
  const Zone east{"east", {{4.5, 0.0}, {9.0, 0.0}, {9.0, 7.0}, {4.5, 7.0}}};
  for (const auto& [zone, expected_x, expected_y] :
       {std::tuple{west, 3.0, 2.5}, std::tuple{east, 9.0 - 3.0, 7.0 - 2.5}}) {
    const auto sols = matcher.match(*scan, matcher.regionOf({zone}));
    ASSERT_FALSE(sols.empty()) << zone.name;
    EXPECT_NEAR(sols[0].pose.x, expected_x, 0.2) << zone.name;
    EXPECT_NEAR(sols[0].pose.y, expected_y, 0.2) << zone.name;
    for (const auto& s : sols) EXPECT_EQ(s.pose.x < 4.5, zone.name == "west") << zone.name << " " << s.pose.x;
    EXPECT_LT(matcher.lastNodesScored(), whole_nodes) << zone.name;
  }
  ASSERT_FALSE(whole.empty());
  EXPECT_THROW(matcher.match(*scan, cv::Mat::ones(3, 3, CV_8U)), std::invalid_argument);
}

}  // namespace
}  // namespace krp
