// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/yolo_pose_decode.h"

#include <gtest/gtest.h>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {
namespace {

constexpr int kClasses = 2;
constexpr int kKeypoints = 2;
constexpr int kChannels = 4 + kClasses + 3 * kKeypoints;

struct Anchor {
  float cx, cy, w, h;
  float scores[kClasses];
  float kpts[3 * kKeypoints];
};

Tensor output(const std::vector<Anchor>& anchors) {
  Tensor t;
  const int n = static_cast<int>(anchors.size());
  t.shape = {1, kChannels, n};
  t.values.assign(static_cast<size_t>(kChannels) * n, 0.0f);
  for (int a = 0; a < n; ++a) {
    const auto& an = anchors[a];
    const float row[kChannels] = {an.cx,      an.cy,      an.w,       an.h,       an.scores[0], an.scores[1],
                                  an.kpts[0], an.kpts[1], an.kpts[2], an.kpts[3], an.kpts[4],   an.kpts[5]};
    for (int c = 0; c < kChannels; ++c) t.values[static_cast<size_t>(c) * n + a] = row[c];
  }
  return t;
}

TEST(YoloPoseDecode, KeepsBestClassAndDropsLowScores) {
  const auto dets = decodeYoloPose(output({{50, 50, 20, 20, {0.1f, 0.9f}, {40, 45, 0.8f, 60, 55, 0.2f}},
                                           {100, 100, 10, 10, {0.2f, 0.1f}, {0, 0, 0, 0, 0, 0}}}),
                                   kClasses, kKeypoints, 160, 160);
  ASSERT_EQ(dets.size(), 1u);
  EXPECT_EQ(dets[0].class_id, 1);
  EXPECT_FLOAT_EQ(dets[0].score, 0.9f);
  EXPECT_FLOAT_EQ(dets[0].x1, 40);
  EXPECT_FLOAT_EQ(dets[0].y2, 60);
  EXPECT_FLOAT_EQ(dets[0].keypoints[1].x, 60);
  EXPECT_FLOAT_EQ(dets[0].keypoints[1].visibility, 0.2f);
}

TEST(YoloPoseDecode, SuppressesOverlapsWithinAClassOnly) {
  // Two heavily overlapping boxes of class 0 and one of class 1 at the same place.
  const auto dets = decodeYoloPose(output({{50, 50, 20, 20, {0.8f, 0.0f}, {}},
                                           {51, 50, 20, 20, {0.9f, 0.0f}, {}},
                                           {50, 50, 20, 20, {0.0f, 0.7f}, {}}}),
                                   kClasses, kKeypoints, 160, 160);
  ASSERT_EQ(dets.size(), 2u);
  EXPECT_FLOAT_EQ(dets[0].score, 0.9f);  // highest score first
  EXPECT_EQ(dets[0].class_id, 0);
  EXPECT_EQ(dets[1].class_id, 1);
}

TEST(YoloPoseDecode, KeepsDistantBoxesOfOneClass) {
  const auto dets = decodeYoloPose(output({{20, 20, 10, 10, {0.8f, 0.0f}, {}}, {120, 120, 10, 10, {0.6f, 0.0f}, {}}}),
                                   kClasses, kKeypoints, 160, 160);
  EXPECT_EQ(dets.size(), 2u);
}

TEST(YoloPoseDecode, ClipsBoxesAndKeypointsToTheImage) {
  const auto dets =
      decodeYoloPose(output({{5, 150, 30, 30, {0.9f, 0.0f}, {-3, 170, 0.5f, 80, 80, 0.5f}}}), kClasses, kKeypoints, 160,
                     160);
  ASSERT_EQ(dets.size(), 1u);
  EXPECT_FLOAT_EQ(dets[0].x1, 0);
  EXPECT_FLOAT_EQ(dets[0].y2, 160);
  EXPECT_FLOAT_EQ(dets[0].keypoints[0].x, 0);
  EXPECT_FLOAT_EQ(dets[0].keypoints[0].y, 160);
  EXPECT_FLOAT_EQ(dets[0].keypoints[1].x, 80);
}

TEST(YoloPoseDecode, RespectsMaxDetections) {
  PoseDecodeParams p;
  p.max_detections = 1;
  const auto dets = decodeYoloPose(output({{20, 20, 10, 10, {0.8f, 0.0f}, {}}, {120, 120, 10, 10, {0.6f, 0.0f}, {}}}),
                                   kClasses, kKeypoints, 160, 160, p);
  ASSERT_EQ(dets.size(), 1u);
  EXPECT_FLOAT_EQ(dets[0].score, 0.8f);
}

TEST(YoloPoseDecode, RejectsAnOutputOfTheWrongShape) {
  Tensor t;
  t.shape = {1, kChannels + 1, 3};
  t.values.assign(static_cast<size_t>(kChannels + 1) * 3, 0.0f);
  EXPECT_THROW(decodeYoloPose(t, kClasses, kKeypoints, 160, 160), InputError);
}

}  // namespace
}  // namespace krp
