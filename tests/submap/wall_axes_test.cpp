// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/wall_axes.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/submap/submap_builder.h"
#include "support/test_maps.h"

namespace krp {
namespace {

constexpr double kDeg = M_PI / 180.0;

/// Difference of two directions modulo a quarter turn, in (-45, 45] deg.
double quarterTurnDiff(double a, double b) {
  double d = std::remainder(a - b, M_PI / 2);
  return d;
}

mrpt::obs::CObservation2DRangeScan::Ptr scanAt(const mrpt::maps::COccupancyGridMap2D& world,
                                                const mrpt::poses::CPose2D& pose, bool noisy) {
  LidarProfile p = lidarProfileByName("omni_12m");
  if (!noisy) p.range_noise_std_m = 0, p.dropout_probability = 0;
  Rng rng(3);
  return ScanSimulator(p).simulate(world, pose, rng);
}

// A round room: no wall direction dominates.
mrpt::maps::COccupancyGridMap2D roundRoom(double radius_m) {
  mrpt::maps::COccupancyGridMap2D g(-radius_m - 1, radius_m + 1, -radius_m - 1, radius_m + 1, 0.05f);
  g.fill(1.0f);
  for (unsigned y = 0; y < g.getSizeY(); ++y)
    for (unsigned x = 0; x < g.getSizeX(); ++x)
      if (std::hypot(g.idx2x(x), g.idx2y(y)) >= radius_m) g.setCell(x, y, 0.0f);
  return g;
}

// A rectangular room turned by `angle_rad` about the origin: its walls run at that angle.
mrpt::maps::COccupancyGridMap2D turnedRoom(double angle_rad) {
  mrpt::maps::COccupancyGridMap2D g(-8, 8, -8, 8, 0.05f);
  g.fill(0.5f);
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  for (unsigned y = 0; y < g.getSizeY(); ++y)
    for (unsigned x = 0; x < g.getSizeX(); ++x) {
      const double wx = g.idx2x(x), wy = g.idx2y(y);
      const double u = std::abs(c * wx + s * wy), v = std::abs(-s * wx + c * wy);  // room frame
      if (u < 5.0 && v < 3.0) g.setCell(x, y, 1.0f);
      else if (u < 5.2 && v < 3.2) g.setCell(x, y, 0.0f);
    }
  return g;
}

TEST(WallAxes, ScanGivesTheWallsDirectionInTheRobotFrameWhateverTheHeading) {
  const auto room = test::asymmetricRoom();
  for (double heading_deg : {0.0, 17.0, -33.0, 71.0, 150.0, -100.0}) {
    const auto scan = scanAt(room, mrpt::poses::CPose2D(5.0, 3.5, heading_deg * kDeg), true);
    const auto axes = scanWallAxes(*scan);
    ASSERT_TRUE(axes.found) << heading_deg;
    EXPECT_GE(axes.angle_rad, -M_PI / 4);
    EXPECT_LT(axes.angle_rad, M_PI / 4);
    // Map walls run along x and y, so in the robot frame they are at -heading (mod 90 deg).
    EXPECT_NEAR(quarterTurnDiff(axes.angle_rad, -heading_deg * kDeg), 0.0, 1.0 * kDeg) << heading_deg;
    EXPECT_GT(axes.support, 0.5);
  }
}

TEST(WallAxes, RoundRoomHasNoAxes) {
  const auto scan = scanAt(roundRoom(4.0), mrpt::poses::CPose2D(0.5, 0.3, 0.2), false);
  const auto axes = scanWallAxes(*scan);
  EXPECT_FALSE(axes.found);
  EXPECT_LT(axes.support, 0.2);
}

TEST(WallAxes, MapAxesOfAnAxisAlignedMapAreZero) {
  const auto axes = mapWallAxes(test::asymmetricRoom());
  ASSERT_TRUE(axes.found);
  EXPECT_NEAR(axes.angle_rad, 0.0, 1.0 * kDeg);
  const auto turned = mapWallAxes(turnedRoom(20.0 * kDeg));
  ASSERT_TRUE(turned.found);
  EXPECT_NEAR(turned.angle_rad, 20.0 * kDeg, 1.0 * kDeg);  // counter-clockwise in the map frame
  const auto round = mapWallAxes(roundRoom(4.0));
  EXPECT_FALSE(round.found) << round.support;
}

TEST(WallAxes, FourCandidateHeadingsAQuarterTurnApartOneOfThemTheTruth) {
  const auto room = test::asymmetricRoom();
  const double heading = 130.0 * kDeg;
  const auto scan = scanAt(room, mrpt::poses::CPose2D(5.0, 3.5, heading), true);
  const auto headings = wallAlignedImageHeadings(scanWallAxes(*scan));
  ASSERT_EQ(headings.size(), 4u);
  for (size_t k = 1; k < 4; ++k)
    EXPECT_NEAR(std::abs(mrpt::math::wrapToPi(headings[k] - headings[k - 1])), M_PI / 2, 1e-9);
  EXPECT_NEAR(mrpt::math::wrapToPi(nearestHeading(headings, heading) - heading), 0.0, 1.0 * kDeg);
  EXPECT_DOUBLE_EQ(nearestHeading({0.0, M_PI / 2}, 1.4), M_PI / 2);
  EXPECT_DOUBLE_EQ(nearestHeading({3.1, -1.0}, -3.1), 3.1);  // across the +-180 deg seam
}

// In a map whose walls run at 20 deg, a robot whose scan sees them at 5 deg in its own frame
// stands at 15 deg or a quarter turn from it.
TEST(WallAxes, MapHeadingsLineTheScansWallsUpWithTheMaps) {
  const auto room = turnedRoom(20.0 * kDeg);
  const double heading = 15.0 * kDeg + M_PI / 2;
  const auto scan = scanAt(room, mrpt::poses::CPose2D(1.0, 0.5, heading), true);
  const auto headings = wallAlignedMapHeadings(scanWallAxes(*scan), mapWallAxes(room));
  ASSERT_EQ(headings.size(), 4u);
  for (size_t k = 1; k < 4; ++k)
    EXPECT_NEAR(std::abs(mrpt::math::wrapToPi(headings[k] - headings[k - 1])), M_PI / 2, 1e-9);
  EXPECT_NEAR(mrpt::math::wrapToPi(nearestHeading(headings, heading) - heading), 0.0, 1.5 * kDeg);
  WallAxes scan_axes, map_axes;
  scan_axes.angle_rad = 5.0 * kDeg;
  map_axes.angle_rad = 20.0 * kDeg;
  EXPECT_NEAR(wallAlignedMapHeadings(scan_axes, map_axes).front(), 15.0 * kDeg, 1e-12);
}

TEST(WallAxes, RejectsBadParameters) {
  const auto scan = scanAt(test::asymmetricRoom(), mrpt::poses::CPose2D(5.0, 3.5, 0), false);
  WallAxesParams p;
  p.bin_deg = 0;
  EXPECT_THROW(scanWallAxes(*scan, p), InputError);
  p = {};
  p.min_neighbour_gap_m = 2.0;  // above the max gap
  EXPECT_THROW(mapWallAxes(test::asymmetricRoom(), p), InputError);
}

TEST(WallAlignedSubmap, WallsFallOnImageRowsAndColumnsAndTheRobotFrameRoundTrips) {
  const auto room = test::asymmetricRoom();
  const double heading = 27.0 * kDeg;
  const auto scan = scanAt(room, mrpt::poses::CPose2D(5.0, 3.5, heading), false);
  SubmapParams p;
  p.size_m = 12.8;
  p.size_px = 128;
  p.orientation = SubmapOrientation::kWallAxes;
  const auto headings = submapImageHeadings(*scan, p);
  ASSERT_EQ(headings.size(), 4u);
  const double image_heading = nearestHeading(headings, heading);
  const auto sub = buildSubmap(*scan, p, image_heading);
  EXPECT_DOUBLE_EQ(sub.grid.image_heading_rad, image_heading);
  // Drawn at the robot's map heading, the room's walls are rows and columns: occupied cells
  // crowd onto a few columns (x = 0 and x = 8 m walls) instead of spreading over many.
  auto busiestColumnShare = [](const LocalGrid& g) {
    int best = 0, total = 0;
    for (int c = 0; c < g.sizePx(); ++c) {
      int n = 0;
      for (int r = 0; r < g.sizePx(); ++r) n += g.at(c, r) == CellState::kOccupied;
      best = std::max(best, n);
      total += n;
    }
    return static_cast<double>(best) / total;
  };
  const auto heading_up = buildSubmap(*scan, p);
  EXPECT_GT(busiestColumnShare(sub.grid), 2.0 * busiestColumnShare(heading_up.grid));
  // The west wall (map x = 0.5) is 4.5 m west of the robot: 4.5 m left of the centre column.
  const double centre = 0.5 * (p.size_px - 1), res = p.resolutionM();
  int on_west_wall = 0;
  for (int r = 0; r < p.size_px; ++r)
    for (int dc = -1; dc <= 1; ++dc)
      on_west_wall += sub.grid.at(static_cast<int>(std::lround(centre - 4.5 / res)) + dc, r) == CellState::kOccupied;
  EXPECT_GT(on_west_wall, 20);
  const mrpt::math::TPoint2D p_robot(1.7, -0.4);
  const auto back = sub.grid.pixelToRobot(sub.grid.robotToPixel(p_robot));
  EXPECT_NEAR(back.x, p_robot.x, 1e-12);
  EXPECT_NEAR(back.y, p_robot.y, 1e-12);
  SubmapParams up = p;
  up.orientation = SubmapOrientation::kHeadingUp;
  EXPECT_EQ(submapImageHeadings(*scan, up), std::vector<double>{kHeadingUpRad});
}

TEST(SubmapOrientation, NamesRoundTripAndUnknownNamesAreRefused) {
  for (auto o : {SubmapOrientation::kHeadingUp, SubmapOrientation::kWallAxes})
    EXPECT_EQ(parseOrientation(orientationName(o), "test"), o);
  try {
    parseOrientation("north_up", "manifest.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("heading_up, wall_axes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace krp
