// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/training_map_check.h"

#include <gtest/gtest.h>

#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "support/input_error_message.h"

namespace krp {
namespace {

using test::inputErrorMessage;

const std::string kSource = KRP_SOURCE_DIR;

mrpt::maps::COccupancyGridMap2D worldMap(const std::string& name) {
  return *loadOccupancyMap(readWorld(kSource + "/sim_worlds/" + name + "/" + name + ".world.yaml").map_path).grid;
}

ModelManifest shippedManifest(const std::string& world) { return readModelManifest(kSource + "/models/" + world); }

/// Clears every cell within `radius_m` of the first `count` landmarks (a wall taken out around each).
void eraseAroundLandmarks(mrpt::maps::COccupancyGridMap2D& map, const ModelManifest& m, int count, double radius_m) {
  int done = 0;
  for (const auto& zone : m.landmarks)
    for (const auto& l : zone) {
      if (done++ == count) return;
      for (double y = l.y - radius_m; y <= l.y + radius_m; y += map.getResolution() / 2)
        for (double x = l.x - radius_m; x <= l.x + radius_m; x += map.getResolution() / 2)
          if (std::hypot(x - l.x, y - l.y) <= radius_m) map.setPos(x, y, 1.0f);
    }
}

TEST(TrainingMapCheck, EveryLandmarkLiesOnTheTrainingMapsWalls) {
  for (const char* world : {"office_two_zone", "warehouse"}) {
    const auto map = worldMap(world);
    const auto manifest = shippedManifest(world);
    EXPECT_DOUBLE_EQ(landmarkShareOnWalls(manifest, map), 1.0) << world;
    EXPECT_EQ(inputErrorMessage([&] { requireTrainingMap(manifest, map); }), "") << world;
  }
}

TEST(TrainingMapCheck, AnotherWorldsMapOfTheSameCellSizeIsRefused) {
  const auto office = shippedManifest("office_two_zone");
  for (const char* world : {"warehouse", "large_floor", "corridor", "empty_hall"}) {
    const auto map = worldMap(world);
    EXPECT_LT(landmarkShareOnWalls(office, map), TrainingMapCheckParams{}.min_landmark_share_on_walls) << world;
    const auto message = inputErrorMessage([&] { requireTrainingMap(office, map); });
    EXPECT_NE(message.find("trained on another map (world 'office_two_zone')"), std::string::npos) << world << ": " << message;
    EXPECT_NE(message.find("manifest.json"), std::string::npos) << message;
  }
  const auto message = inputErrorMessage([&] { requireTrainingMap(shippedManifest("warehouse"), worldMap("office_two_zone")); });
  EXPECT_NE(message.find("world 'warehouse'"), std::string::npos) << message;
}

// A map edited after training (a wall moved, a rack taken out) keeps most landmarks: a few
// missing pass, too many do not.
TEST(TrainingMapCheck, AFewEditedLandmarksPassManyDoNot) {
  const auto manifest = shippedManifest("office_two_zone");  // 24 landmarks
  auto edited = worldMap("office_two_zone");
  eraseAroundLandmarks(edited, manifest, 4, 0.5);  // two of them are shared by both zones: 6 of 24 go
  EXPECT_DOUBLE_EQ(landmarkShareOnWalls(manifest, edited), 18.0 / 24.0);
  EXPECT_EQ(inputErrorMessage([&] { requireTrainingMap(manifest, edited); }), "");
  eraseAroundLandmarks(edited, manifest, 8, 0.5);
  EXPECT_LT(landmarkShareOnWalls(manifest, edited), 0.75);
  EXPECT_NE(inputErrorMessage([&] { requireTrainingMap(manifest, edited); }).find("only "), std::string::npos);
}

TEST(TrainingMapCheck, LandmarksOutsideTheMapDoNotCount) {
  auto manifest = shippedManifest("office_two_zone");
  const auto map = worldMap("office_two_zone");
  for (auto& zone : manifest.landmarks)
    for (auto& l : zone) l.x += map.getXMax();  // the whole set moved off the map's east edge
  EXPECT_DOUBLE_EQ(landmarkShareOnWalls(manifest, map), 0.0);
}

// Even with the rest on its walls, one landmark off the map means another map.
TEST(TrainingMapCheck, ALandmarkOutsideTheMapIsRefused) {
  auto manifest = shippedManifest("office_two_zone");
  const auto map = worldMap("office_two_zone");
  manifest.landmarks[1][0].x = map.getXMax() + 1.0;
  EXPECT_GE(landmarkShareOnWalls(manifest, map), TrainingMapCheckParams{}.min_landmark_share_on_walls);
  const auto message = inputErrorMessage([&] { requireTrainingMap(manifest, map); });
  EXPECT_NE(message.find("landmark of zone 'east_wing' lies outside the map"), std::string::npos) << message;
}

TEST(TrainingMapCheck, AnotherCellSizeIsRefusedFirst) {
  const auto manifest = shippedManifest("office_two_zone");
  const auto map = worldMap("office_two_zone");
  mrpt::maps::COccupancyGridMap2D coarse;
  coarse.setSize(map.getXMin(), map.getXMax(), map.getYMin(), map.getYMax(), 0.1f);
  const auto message = inputErrorMessage([&] { requireTrainingMap(manifest, coarse); });
  EXPECT_NE(message.find("trained on a map of 0.05"), std::string::npos) << message;
}

}  // namespace
}  // namespace krp
