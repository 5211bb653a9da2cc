// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/grid_image.h"
#include "mrpt_krp_plugin/sim/world_builders.h"
#include "mrpt_krp_plugin/zones/auto_zoning.h"
#include "mrpt_krp_plugin/zones/zone_drawing.h"
#include "mrpt_krp_plugin/zones/zone_validation.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"
#include "support/test_maps.h"

namespace krp {
namespace {

TEST(ZonesYaml, RoundTripsAndLooksUpPoints) {
  const auto dir = test::tempDir("zones_rt");
  const std::vector<Zone> zones = {{"left", {{0.6, 0.6}, {4.0, 0.6}, {4.0, 6.0}, {0.6, 6.0}}},
                                   {"right", {{4.1, 0.6}, {8.4, 0.6}, {8.4, 6.0}, {4.1, 6.0}}}};
  writeZonesYaml(zones, dir + "/z.yaml");
  const auto back = readZonesYaml(dir + "/z.yaml");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].name, "right");
  EXPECT_NEAR(back[1].polygon[2].x, 8.4, 1e-9);
  const auto room = test::asymmetricRoom();
  const ZoneIndex index(room, back);
  EXPECT_EQ(index.zoneAt({2.0, 3.0}), 0);
  EXPECT_EQ(index.zoneAt({7.0, 3.0}), 1);
  EXPECT_EQ(index.zoneAt({-5.0, 3.0}), -1);
  EXPECT_TRUE(findZoneProblems(room, back).empty());
}

TEST(ZonesYaml, RejectsMalformedFiles) {
  const auto dir = test::tempDir("zones_bad");
  test::writeText(dir + "/empty.yaml", "zones: []\n");
  test::writeText(dir + "/two_points.yaml", "zones:\n  - name: a\n    polygon: [[0, 0], [1, 1]]\n");
  test::writeText(dir + "/dup.yaml",
                  "zones:\n  - name: a\n    polygon: [[0,0],[1,0],[1,1]]\n  - name: a\n    polygon: [[0,0],[1,0],[1,1]]\n");
  test::writeText(dir + "/key.yaml", "zones:\n  - name: a\n    colour: red\n    polygon: [[0,0],[1,0],[1,1]]\n");
  test::writeText(dir + "/nan.yaml", "zones:\n  - name: a\n    polygon: [[0,0],[.nan,0],[1,1]]\n");
  for (const char* f : {"empty", "two_points", "dup", "key", "nan", "missing"})
    EXPECT_THROW(readZonesYaml(dir + "/" + f + ".yaml"), InputError) << f;
}

TEST(ZoneValidation, FindsOutsideOverlapAndNoFreeSpace) {
  const auto room = test::asymmetricRoom();  // free space within (0.5, 8.5) x (0.5, 6.5)
  const Zone a{"a", {{0.6, 0.6}, {5.0, 0.6}, {5.0, 6.0}, {0.6, 6.0}}};
  const Zone b_overlapping{"b", {{4.0, 0.6}, {8.4, 0.6}, {8.4, 6.0}, {4.0, 6.0}}};
  const Zone outside{"far", {{20.0, 20.0}, {21.0, 20.0}, {21.0, 21.0}}};
  const Zone in_wall{"wall", {{0.0, 0.0}, {0.3, 0.0}, {0.3, 0.3}, {0.0, 0.3}}};
  auto joined = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += x + "\n";
    return s;
  };
  const auto overlap = joined(findZoneProblems(room, {a, b_overlapping}));
  EXPECT_NE(overlap.find("overlap"), std::string::npos) << overlap;
  const auto out = joined(findZoneProblems(room, {a, outside}));
  EXPECT_NE(out.find("outside the map"), std::string::npos) << out;
  const auto nofree = joined(findZoneProblems(room, {a, in_wall}));
  EXPECT_NE(nofree.find("free space"), std::string::npos) << nofree;
  EXPECT_THROW(validateZones(room, {}, "test"), InputError);
}

TEST(AutoZoning, FollowsRoomsAndHitsTargetSize) {
  // The office world: rooms off a corridor. With a target about one room, zoning must
  // produce several valid zones, each a sensible size.
  const auto world = buildOfficeTwoZone(1);
  AutoZoningParams p;
  p.target_area_m2 = 60.0;
  const auto zones = autoZone(world.map, p);
  EXPECT_TRUE(findZoneProblems(world.map, zones).empty());
  EXPECT_GE(zones.size(), 6u);
  EXPECT_LE(zones.size(), 25u);
  for (const auto& z : zones) EXPECT_LT(polygonAreaM2(z.polygon), 4.0 * p.target_area_m2) << z.name;
  // Deterministic: the same map and parameters give the same zones.
  const auto again = autoZone(world.map, p);
  ASSERT_EQ(again.size(), zones.size());
  EXPECT_EQ(again.front().polygon.size(), zones.front().polygon.size());
}

// Occupies the outline of the rectangle [x0, x1] x [y0, y1] (a wall one cell thick).
void drawWallBox(mrpt::maps::COccupancyGridMap2D& g, double x0, double y0, double x1, double y1) {
  for (int cx = g.x2idx(x0); cx <= g.x2idx(x1); ++cx)
    for (int cy = g.y2idx(y0); cy <= g.y2idx(y1); ++cy)
      if (cx == g.x2idx(x0) || cx == g.x2idx(x1) || cy == g.y2idx(y0) || cy == g.y2idx(y1)) g.setCell(cx, cy, 0.0f);
}

TEST(AutoZoning, EnclosedRoomsAndTinyPocketsStillGiveValidZones) {
  // A hall with a closed room standing inside it (the hall's outline encloses the room)
  // and a closed pocket too small for a robot: zones must neither overlap nor be empty.
  mrpt::maps::COccupancyGridMap2D g(0, 30, 0, 20, 0.1);
  g.fill(1.0f);
  drawWallBox(g, 0.05, 0.05, 29.9, 19.9);
  drawWallBox(g, 10, 6, 18, 13);        // the inner room
  drawWallBox(g, 24, 3, 24.9, 3.9);    // a 0.7 m^2 pocket
  AutoZoningParams p;
  p.target_area_m2 = 200.0;
  const auto zones = autoZone(g, p);
  const auto problems = findZoneProblems(g, zones);
  std::string all;
  for (const auto& s : problems) all += s + "; ";
  EXPECT_TRUE(problems.empty()) << all;
  EXPECT_GE(zones.size(), 2u);
}

TEST(AutoZoning, RefusesATargetAreaThatIsNotPositive) {
  mrpt::maps::COccupancyGridMap2D g(0, 10, 0, 10, 0.1);
  g.fill(1.0f);
  drawWallBox(g, 0.05, 0.05, 9.9, 9.9);
  AutoZoningParams p;
  for (const double bad : {0.0, -3.0, std::nan("")}) {
    p.target_area_m2 = bad;
    EXPECT_THROW(autoZone(g, p), InputError) << bad;
  }
  p.target_area_m2 = 20.0;
  p.merge_below_factor = 2.0;  // above the split factor: would merge what it splits
  EXPECT_THROW(autoZone(g, p), InputError);
  p.merge_below_factor = AutoZoningParams{}.merge_below_factor;
  EXPECT_FALSE(autoZone(g, p).empty());
}

TEST(AutoZoning, LargeFloorGetsAtLeastTwelveValidZones) {
  const auto world = buildLargeFloor(1);
  EXPECT_GE(world.zones.size(), 12u);
  EXPECT_TRUE(findZoneProblems(world.map, world.zones).empty());
  EXPECT_GE(freeAreaM2(world.map), 3000.0);
}

// The degenerate scenes of scripts/bench_degenerate.sh are what they claim: plain, valid worlds.
TEST(WorldBuilders, DegenerateScenesHaveValidZonesAndTheirSize) {
  const auto corridor = buildWorld("corridor", 1);
  EXPECT_TRUE(findZoneProblems(corridor.map, corridor.zones).empty());
  EXPECT_NEAR(freeAreaM2(corridor.map), 60.0 * 2.4, 15.0);
  const auto hall = buildWorld("empty_hall", 1);
  EXPECT_TRUE(findZoneProblems(hall.map, hall.zones).empty());
  EXPECT_NEAR(freeAreaM2(hall.map), 40.0 * 30.0, 30.0);
}

// The wings meet along room walls: free space crosses from one zone to the other only in the
// 2.5 m corridor, never through a room (which the classifier would see under two names).
TEST(WorldBuilders, OfficeWingsMeetOnlyInTheCorridor) {
  const auto world = buildOfficeTwoZone(1);
  EXPECT_TRUE(findZoneProblems(world.map, world.zones).empty());
  const cv::Mat free = freeMask(world.map), labels = rasterizeZones(world.map, world.zones);
  int unzoned_free = 0, crossings = 0;
  for (int r = 0; r < free.rows; ++r)
    for (int c = 0; c < free.cols; ++c) {
      if (!free.at<uint8_t>(r, c)) continue;
      const int zone = labels.at<int>(r, c);
      if (zone < 0) ++unzoned_free;
      if (c + 1 < free.cols && free.at<uint8_t>(r, c + 1) && labels.at<int>(r, c + 1) != zone) ++crossings;
      if (r + 1 < free.rows && free.at<uint8_t>(r + 1, c) && labels.at<int>(r + 1, c) != zone) ++crossings;
    }
  EXPECT_EQ(unzoned_free, 0);
  const double corridor_width_m = 2.5;
  EXPECT_GT(crossings, 0);
  EXPECT_LE(crossings, corridor_width_m / kWorldResolutionM);
}

// The unseen wing is office_two_zone plus a wing: every cell of the office up to its east wall is
// the same, the two wings are the same zones, and the wing is a third zone.
TEST(WorldBuilders, UnseenWingKeepsTheOfficeAndAddsAZone) {
  const auto office = buildOfficeTwoZone(1);
  const auto extended = buildOfficeUnseenWing(1);
  EXPECT_TRUE(findZoneProblems(extended.map, extended.zones).empty());
  ASSERT_EQ(extended.zones.size(), 3u);
  EXPECT_EQ(extended.zones[2].name, "unseen_wing");
  EXPECT_EQ(extended.trial_start_zone, "unseen_wing");
  for (size_t z = 0; z < 2; ++z) {
    EXPECT_EQ(extended.zones[z].name, office.zones[z].name);
    ASSERT_EQ(extended.zones[z].polygon.size(), office.zones[z].polygon.size());
    for (size_t v = 0; v < office.zones[z].polygon.size(); ++v) {
      EXPECT_EQ(extended.zones[z].polygon[v].x, office.zones[z].polygon[v].x);
      EXPECT_EQ(extended.zones[z].polygon[v].y, office.zones[z].polygon[v].y);
    }
  }
  ASSERT_EQ(extended.map.getYMin(), office.map.getYMin());
  ASSERT_EQ(extended.map.getXMin(), office.map.getXMin());
  ASSERT_EQ(extended.map.getSizeY(), office.map.getSizeY());
  ASSERT_GT(extended.map.getSizeX(), office.map.getSizeX());
  // West of the office's east wall (at 35 m; the door is cut 0.2 m either side of it) every cell
  // is the same; beyond it the wing begins.
  const unsigned east_wall_cell = office.map.x2idx(35.0 - 0.25);
  int differing = 0;
  for (unsigned y = 0; y < office.map.getSizeY(); ++y)
    for (unsigned x = 0; x < east_wall_cell; ++x) differing += office.map.getCell(x, y) != extended.map.getCell(x, y);
  EXPECT_EQ(differing, 0);
}

// The warehouse's quadrants meet in the cross aisle and in an aisle between two rack rows: no rack
// is cut in two, so the only obstacles a boundary crosses are the four building walls.
TEST(WorldBuilders, WarehouseQuadrantsCutNoRack) {
  const auto world = buildWarehouse(1);
  EXPECT_TRUE(findZoneProblems(world.map, world.zones).empty());
  EXPECT_EQ(world.zones.size(), 4u);
  const cv::Mat occupied = occupiedMask(world.map), labels = rasterizeZones(world.map, world.zones);
  int crossings = 0;
  for (int r = 0; r + 1 < occupied.rows; ++r)
    for (int c = 0; c + 1 < occupied.cols; ++c) {
      if (!occupied.at<uint8_t>(r, c)) continue;
      const int zone = labels.at<int>(r, c);
      if (occupied.at<uint8_t>(r, c + 1) && labels.at<int>(r, c + 1) != zone) ++crossings;
      if (occupied.at<uint8_t>(r + 1, c) && labels.at<int>(r + 1, c) != zone) ++crossings;
    }
  // A building wall is a few cells thick; one rack cut across its 1.1 m depth alone would add 22.
  const int building_walls_crossed = 4, cells_per_wall_allowed = 5;
  EXPECT_GT(crossings, 0);
  EXPECT_LE(crossings, building_walls_crossed * cells_per_wall_allowed);
}

TEST(ZoneDrawing, WritesAPngOfTheMapSize) {
  const auto dir = test::tempDir("zones_png");
  const auto world = buildOfficeTwoZone(1);
  writeZonesPng(world.map, world.zones, dir + "/z.png");
  const cv::Mat img = cv::imread(dir + "/z.png");
  ASSERT_FALSE(img.empty());
  EXPECT_GE(img.cols, static_cast<int>(world.map.getSizeX()));
  EXPECT_FALSE(std::filesystem::exists(dir + "/z.png.tmp"));
}

}  // namespace
}  // namespace krp
