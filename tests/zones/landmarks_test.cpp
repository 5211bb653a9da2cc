// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <filesystem>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/sim/world_builders.h"
#include "mrpt_krp_plugin/zones/landmark_drawing.h"
#include "mrpt_krp_plugin/zones/landmarks.h"
#include "mrpt_krp_plugin/zones/landmarks_yaml.h"
#include "support/test_maps.h"

namespace krp {
namespace {

TEST(Landmarks, RoomCornersAreFoundAndSpread) {
  // The 8 x 6 m room (walls from 0.5 to 8.5 and 0.5 to 6.5, an L-shaped inner wall and a
  // box) as one zone: its four outer corners
  // must be among the landmarks, and no two landmarks closer than the spacing.
  const auto room = test::asymmetricRoom();
  Zone z{"room", {{0.7, 0.7}, {8.3, 0.7}, {8.3, 6.3}, {0.7, 6.3}}};
  LandmarkParams p;
  p.keypoints_per_zone = 8;
  const auto lm = extractLandmarks(room, {z}, p);
  ASSERT_EQ(lm.size(), 1u);
  ASSERT_EQ(lm[0].points.size(), 8u);
  for (size_t i = 0; i < lm[0].points.size(); ++i)
    for (size_t j = i + 1; j < lm[0].points.size(); ++j)
      EXPECT_GE((lm[0].points[i] - lm[0].points[j]).norm(), p.min_spacing_m - 1e-9);
  int corners_found = 0;
  for (const auto& corner : {mrpt::math::TPoint2D{0.5, 0.5}, {8.5, 0.5}, {8.5, 6.5}, {0.5, 6.5}}) {
    double nearest = 1e9;
    for (const auto& q : lm[0].points) nearest = std::min(nearest, (q - corner).norm());
    corners_found += nearest < 0.3;
  }
  EXPECT_GE(corners_found, 3);
  // Deterministic.
  const auto again = extractLandmarks(room, {z}, p);
  EXPECT_EQ(again[0].points[3].x, lm[0].points[3].x);
}

TEST(Landmarks, WarehouseZonesEachGetK) {
  const auto world = buildWarehouse(1);
  const auto lm = extractLandmarks(world.map, world.zones);
  ASSERT_EQ(lm.size(), world.zones.size());
  for (const auto& z : lm) EXPECT_EQ(z.points.size(), 12u) << z.zone;
}

TEST(Landmarks, YamlRoundTripAndBadFiles) {
  const auto dir = test::tempDir("landmarks_yaml");
  const auto room = test::asymmetricRoom();
  Zone z{"room", {{0.7, 0.7}, {8.3, 0.7}, {8.3, 6.3}, {0.7, 6.3}}};
  LandmarkParams p;
  p.keypoints_per_zone = 5;
  const auto lm = extractLandmarks(room, {z}, p);
  writeLandmarksYaml(lm, p, dir + "/lm.yaml");
  const auto back = readLandmarksYaml(dir + "/lm.yaml");
  ASSERT_EQ(back.size(), 1u);
  ASSERT_EQ(back[0].points.size(), 5u);
  EXPECT_NEAR(back[0].points[4].y, lm[0].points[4].y, 1e-9);
  writeLandmarksPng(room, {z}, lm, dir + "/lm.png");
  EXPECT_TRUE(std::filesystem::exists(dir + "/lm.png"));

  test::writeText(dir + "/short.yaml", "keypoints_per_zone: 4\nzones:\n  - zone: a\n    points: [[0,0],[1,0],[1,1]]\n");
  test::writeText(dir + "/key.yaml", "keypoints_per_zone: 3\ncolour: red\nzones: []\n");
  test::writeText(dir + "/nan.yaml", "keypoints_per_zone: 3\nzones:\n  - zone: a\n    points: [[0,0],[.nan,0],[1,1]]\n");
  for (const char* f : {"short.yaml", "key.yaml", "nan.yaml", "missing.yaml"})
    EXPECT_THROW(readLandmarksYaml(dir + "/" + f), InputError) << f;
  LandmarkParams too_few;
  too_few.keypoints_per_zone = 2;
  EXPECT_THROW(extractLandmarks(room, {z}, too_few), InputError);
}

}  // namespace
}  // namespace krp
