// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/map/mrpt_gridmap_reader.h"
#include "support/test_maps.h"

namespace krp {
namespace {

using test::tempDir;
using test::writeText;

// A 4 x 3 PGM: row 0 (top) = 0 0 254 254, row 1 = 205 205 205 205, row 2 = 254 254 254 0.
std::string tinyPgm() {
  std::string px = {char(0), char(0), char(254), char(254), char(205), char(205), char(205), char(205),
                    char(254), char(254), char(254), char(0)};
  return "P5\n# comment\n4 3\n255\n" + px;
}

std::string yaml(const std::string& extra = "", const std::string& image = "m.pgm") {
  return "image: " + image + "\nresolution: 0.5\norigin: [1.0, -2.0, 0.0]\n" + extra;
}

float occupancy(const OccupancyMap& m, int cx, int cy) { return 1.0f - m.grid->getCell(cx, cy); }

TEST(RosMapYaml, ReadsTrinaryWithRowFlipAndOrigin) {
  const auto dir = tempDir("ros_ok");
  writeText(dir + "/m.pgm", tinyPgm());
  writeText(dir + "/m.yaml", yaml());
  const auto m = loadOccupancyMap(dir + "/m.yaml");
  ASSERT_EQ(m.grid->getSizeX(), 4u);
  ASSERT_EQ(m.grid->getSizeY(), 3u);
  EXPECT_NEAR(m.grid->getXMin(), 1.0, 1e-6);
  EXPECT_NEAR(m.grid->getYMin(), -2.0, 1e-6);
  EXPECT_NEAR(m.grid->getResolution(), 0.5, 1e-6);
  // Image row 0 is the top, i.e. the grid's highest y row (cy = 2).
  EXPECT_NEAR(occupancy(m, 0, 2), 1.0, 0.01);
  EXPECT_NEAR(occupancy(m, 2, 2), 0.0, 0.01);
  EXPECT_NEAR(occupancy(m, 0, 1), 0.5, 0.01);  // 205 is unknown in trinary
  EXPECT_NEAR(occupancy(m, 3, 0), 1.0, 0.01);
  EXPECT_NEAR(occupancy(m, 0, 0), 0.0, 0.01);
}

TEST(RosMapYaml, NegateSwapsMeaning) {
  const auto dir = tempDir("ros_negate");
  writeText(dir + "/m.pgm", tinyPgm());
  writeText(dir + "/m.yaml", yaml("negate: 1\n"));
  const auto m = loadOccupancyMap(dir + "/m.yaml");
  EXPECT_NEAR(occupancy(m, 0, 2), 0.0, 0.01);  // black is free when negated
  EXPECT_NEAR(occupancy(m, 2, 2), 1.0, 0.01);
}

TEST(RosMapYaml, ScaleModeKeepsIntermediateValues) {
  const auto dir = tempDir("ros_scale");
  writeText(dir + "/m.pgm", tinyPgm());
  writeText(dir + "/m.yaml", yaml("mode: scale\n"));
  const auto m = loadOccupancyMap(dir + "/m.yaml");
  // 205 -> p = 50/255 = 0.196, just at free_thresh: scaled to ~0 occupancy, not unknown.
  const double p = (255.0 - 205.0) / 255.0;
  const double expected = p < 0.196 ? 0.0 : (p - 0.196) / (0.65 - 0.196);
  EXPECT_NEAR(occupancy(m, 0, 1), expected, 0.02);
}

TEST(RosMapYaml, RawModeReadsValuesDirectly) {
  const auto dir = tempDir("ros_raw");
  std::string px = {char(0), char(100), char(50), char(255)};
  writeText(dir + "/m.pgm", "P5\n4 1\n255\n" + px);
  writeText(dir + "/m.yaml", yaml("mode: raw\n"));
  const auto m = loadOccupancyMap(dir + "/m.yaml");
  EXPECT_NEAR(occupancy(m, 0, 0), 0.0, 0.01);
  EXPECT_NEAR(occupancy(m, 1, 0), 1.0, 0.01);
  EXPECT_NEAR(occupancy(m, 2, 0), 0.5, 0.01);
  EXPECT_NEAR(occupancy(m, 3, 0), 0.5, 0.01);  // 255 = unknown (-1)
}

TEST(RosMapYaml, ResolvesImageRelativeToYamlFolder) {
  const auto dir = tempDir("ros_rel");
  writeText(dir + "/maps/img/m.pgm", tinyPgm());
  writeText(dir + "/maps/m.yaml", yaml("", "img/m.pgm"));
  EXPECT_NO_THROW(loadOccupancyMap(dir + "/maps/m.yaml"));
}

TEST(RosMapYaml, WriterRoundTrips) {
  const auto dir = tempDir("ros_rt");
  const auto room = test::asymmetricRoom();
  writeRosMap(room, dir + "/room.yaml");
  const auto back = loadOccupancyMap(dir + "/room.yaml");
  ASSERT_EQ(back.grid->getSizeX(), room.getSizeX());
  ASSERT_EQ(back.grid->getSizeY(), room.getSizeY());
  EXPECT_NEAR(back.grid->getXMin(), room.getXMin(), 1e-6);
  for (unsigned y = 0; y < room.getSizeY(); y += 7)
    for (unsigned x = 0; x < room.getSizeX(); x += 7) EXPECT_NEAR(back.grid->getCell(x, y), room.getCell(x, y), 0.02);
  EXPECT_EQ(countFreeCells(*back.grid), countFreeCells(room));
}

struct BadMapCase {
  std::string name, yaml_text, pgm, expected_fragment;
};

class MalformedRosMap : public ::testing::TestWithParam<BadMapCase> {};

TEST_P(MalformedRosMap, FailsWithANamedProblem) {
  const auto& c = GetParam();
  const auto dir = tempDir("ros_bad_" + c.name);
  if (!c.pgm.empty()) writeText(dir + "/m.pgm", c.pgm);
  if (!c.yaml_text.empty()) writeText(dir + "/m.yaml", c.yaml_text);
  try {
    loadOccupancyMap(dir + "/m.yaml");
    FAIL() << "expected an InputError for " << c.name;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(c.expected_fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(dir), std::string::npos) << "the message names the file: " << e.what();
  }
}

const std::string kAllOccupied = "P5\n2 2\n255\n" + std::string(4, char(0));

INSTANTIATE_TEST_SUITE_P(
    Cases, MalformedRosMap,
    ::testing::Values(
        BadMapCase{"missing_yaml", "", "", "does not exist"},
        BadMapCase{"bad_syntax", "image: [unclosed\n", "", "malformed YAML"},
        BadMapCase{"unknown_key", yaml("colour: blue\n"), tinyPgm(), "unknown key 'colour'"},
        BadMapCase{"no_resolution", "image: m.pgm\norigin: [0, 0, 0]\n", tinyPgm(), "missing required key 'resolution'"},
        BadMapCase{"nan_resolution", "image: m.pgm\nresolution: .nan\norigin: [0, 0, 0]\n", tinyPgm(), "resolution"},
        BadMapCase{"negative_resolution", "image: m.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n", tinyPgm(), "resolution"},
        BadMapCase{"nan_origin", "image: m.pgm\nresolution: 0.05\norigin: [.nan, 0, 0]\n", tinyPgm(), "NaN"},
        BadMapCase{"short_origin", "image: m.pgm\nresolution: 0.05\norigin: [0, 0]\n", tinyPgm(), "origin"},
        BadMapCase{"thresholds_swapped", yaml("occupied_thresh: 0.1\nfree_thresh: 0.9\n"), tinyPgm(), "thresholds"},
        BadMapCase{"bad_mode", yaml("mode: fancy\n"), tinyPgm(), "mode 'fancy'"},
        BadMapCase{"missing_image", yaml(), "", "does not exist"},
        BadMapCase{"truncated_pgm", yaml(), "P5\n4 3\n255\n\x01\x02", "truncated"},
        BadMapCase{"not_an_image", yaml(), "hello, I am not a PGM", "not a PGM"},
        BadMapCase{"absurd_size", yaml(), "P5\n900000 900000\n255\n", "larger than the limit"},
        BadMapCase{"no_free_cell", yaml(), kAllOccupied, "no free cell"},
        BadMapCase{"far_origin", "image: m.pgm\nresolution: 0.05\norigin: [3.0e38, 0, 0]\n", tinyPgm(), "from the origin"},
        // Found by ros_map_fuzzer: a key looked up inside a scalar.
        BadMapCase{"scalar_where_list", "image: m.pgm\nresolution: 0.05\norigin: 7\n", tinyPgm(), "origin"}),
    [](const auto& param_info) { return param_info.param.name; });

TEST(OccupancyMap, GridAndSourceFramesAreInverse) {
  OccupancyMap m{std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom()), 0.7, "test"};
  const mrpt::math::TPose2D p(3.0, 1.5, -2.9);
  const auto source = m.toSourceFrame(p);
  EXPECT_GT(std::hypot(source.x - p.x, source.y - p.y), 0.5);  // the yaw moves it
  const auto back = m.toGridFrame(source);
  EXPECT_NEAR(back.x, p.x, 1e-9);
  EXPECT_NEAR(back.y, p.y, 1e-9);
  EXPECT_NEAR(back.phi, p.phi, 1e-9);
}

TEST(MapLoader, RejectsUnknownExtension) {
  EXPECT_THROW(loadOccupancyMap("/tmp/map.jpeg"), InputError);
}

TEST(MrptGridmap, RoundTripsPlainAndGzip) {
  const auto dir = tempDir("gridmap");
  const auto room = test::asymmetricRoom();
  for (const std::string name : {"room.gridmap", "room.gridmap.gz"}) {
    writeMrptGridmap(room, dir + "/" + name);
    const auto back = loadOccupancyMap(dir + "/" + name);
    ASSERT_EQ(back.grid->getSizeX(), room.getSizeX()) << name;
    ASSERT_EQ(back.grid->getSizeY(), room.getSizeY()) << name;
    EXPECT_FLOAT_EQ(back.grid->getXMin(), room.getXMin()) << name;
    EXPECT_FLOAT_EQ(back.grid->getYMax(), room.getYMax()) << name;
    EXPECT_FLOAT_EQ(back.grid->getResolution(), room.getResolution()) << name;
    for (unsigned y = 0; y < room.getSizeY(); ++y)
      for (unsigned x = 0; x < room.getSizeX(); ++x)
        ASSERT_EQ(back.grid->getCell(x, y), room.getCell(x, y)) << name << " cell " << x << "," << y;
  }
}

TEST(MrptGridmap, RejectsGarbageEmptyAndTruncatedFiles) {
  const auto dir = tempDir("gridmap_bad");
  writeText(dir + "/garbage.gridmap", "this is not an MRPT archive at all");
  writeText(dir + "/empty.gridmap", "");
  EXPECT_THROW(loadOccupancyMap(dir + "/garbage.gridmap"), InputError);
  EXPECT_THROW(loadOccupancyMap(dir + "/empty.gridmap"), InputError);
  EXPECT_THROW(loadOccupancyMap(dir + "/missing.gridmap.gz"), InputError);
  writeMrptGridmap(test::asymmetricRoom(), dir + "/full.gridmap");
  std::ifstream in(dir + "/full.gridmap", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  writeText(dir + "/cut.gridmap", bytes.substr(0, bytes.size() / 2));
  EXPECT_THROW(loadOccupancyMap(dir + "/cut.gridmap"), InputError);
}

// Found by binary_map_fuzzer: MRPT allocates the cells the header announces before reading them.
TEST(MrptGridmap, RefusesAHeaderThatAnnouncesMoreCellsThanTheFileHolds) {
  const auto dir = tempDir("gridmap_header");
  writeMrptGridmap(test::asymmetricRoom(), dir + "/full.gridmap");
  std::ifstream in(dir + "/full.gridmap", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  // size_x sits after the class header (1 + 31 bytes), the version and the bits per cell.
  const size_t size_x_at = 1 + 31 + 1 + 1;
  const uint32_t huge = 60000;
  bytes.replace(size_x_at, sizeof(huge), reinterpret_cast<const char*>(&huge), sizeof(huge));
  writeText(dir + "/huge.gridmap", bytes);
  try {
    loadOccupancyMap(dir + "/huge.gridmap");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the header announces 60000 x"), std::string::npos) << e.what();
  }
  MapLoadParams small;
  small.limits.max_cells = 100;
  EXPECT_THROW(loadOccupancyMap(dir + "/full.gridmap", small), InputError);
}

// A 6 x 4 m room in 3D: walls 0..2 m high, free air inside from 0 to 2 m.
octomap::OcTree octoRoom() {
  octomap::OcTree tree(0.1);
  for (double z = 0.05; z < 2.0; z += 0.1)
    for (double x = 0.05; x < 6.0; x += 0.1)
      for (double y = 0.05; y < 4.0; y += 0.1) {
        const bool wall = x < 0.2 || x > 5.8 || y < 0.2 || y > 3.8;
        tree.updateNode(octomap::point3d(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)), wall);
      }
  return tree;
}

TEST(OctomapSlice, SlicesBinaryAndFullFiles) {
  const auto dir = tempDir("octomap");
  auto tree = octoRoom();
  ASSERT_TRUE(tree.writeBinary(dir + "/room.bt"));
  ASSERT_TRUE(tree.write(dir + "/room.ot"));
  for (const std::string name : {"room.bt", "room.ot"}) {
    const auto m = loadOccupancyMap(dir + "/" + name);
    const auto& g = *m.grid;
    EXPECT_NEAR(1.0 - g.getPos(3.0, 2.0), 0.0, 0.01) << name << ": the middle is free";
    EXPECT_NEAR(1.0 - g.getPos(0.1, 2.0), 1.0, 0.01) << name << ": the west wall is occupied";
    EXPECT_GT(freeAreaM2(g), 15.0) << name;
  }
}

TEST(OctomapSlice, RejectsNonOctomapAndBandMisses) {
  const auto dir = tempDir("octomap_bad");
  writeText(dir + "/fake.bt", "# Octomap OcTree binary file\nid OcTree\nsize 999\nres 0.1\ndata\n\x01");
  writeText(dir + "/plain.ot", "hello");
  EXPECT_THROW(loadOccupancyMap(dir + "/fake.bt"), InputError);
  EXPECT_THROW(loadOccupancyMap(dir + "/plain.ot"), InputError);
  auto tree = octoRoom();
  ASSERT_TRUE(tree.writeBinary(dir + "/room.bt"));
  MapLoadParams high;
  high.octomap.z_min_m = 5.0;
  high.octomap.z_max_m = 6.0;
  EXPECT_THROW(loadOccupancyMap(dir + "/room.bt", high), InputError);
  MapLoadParams inverted;
  inverted.octomap.z_min_m = 1.0;
  inverted.octomap.z_max_m = 0.5;
  EXPECT_THROW(loadOccupancyMap(dir + "/room.bt", inverted), InputError);
}

TEST(SharedData, LoadsWillowGarageWhenPresent) {
  const std::string path = std::string(KRP_SOURCE_DIR) + "/../shared/data/willow/willow-full.yaml";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "third-party map not present: " << path;
  const auto m = loadOccupancyMap(path);
  EXPECT_EQ(m.grid->getSizeX(), 584u);
  EXPECT_EQ(m.grid->getSizeY(), 526u);
  EXPECT_GT(freeAreaM2(*m.grid), 500.0);
}

}  // namespace
}  // namespace krp
