// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/logs/odometry_timeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace krp {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(OdometryTimeline, InterpolatesBetweenThePosesAroundTheTime) {
  const OdometryTimeline t({{1.0, {0.0, 0.0, 0.0}}, {1.2, {1.0, 2.0, 0.4}}}, 0.5);
  const auto p = t.at(1.05);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x, 0.25, 1e-12);
  EXPECT_NEAR(p->y, 0.5, 1e-12);
  EXPECT_NEAR(p->phi, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(t.at(1.2)->x, 1.0);  // a time given is its own pose
}

TEST(OdometryTimeline, HeadingTurnsTheShortWayAcrossPi) {
  const OdometryTimeline t({{0.0, {0, 0, kPi - 0.1}}, {0.2, {0, 0, -kPi + 0.1}}});
  // Halfway through a 0.2 rad turn through pi, not a 6.08 rad turn back through 0.
  EXPECT_NEAR(std::abs(t.at(0.1)->phi), kPi, 1e-9);
}

TEST(OdometryTimeline, LinesOutOfOrderAreSortedAndTheFirstOfATimeKept) {
  const OdometryTimeline t({{2.0, {2, 0, 0}}, {1.0, {1, 0, 0}}, {1.0, {9, 0, 0}}});
  EXPECT_EQ(t.size(), 2u);
  EXPECT_DOUBLE_EQ(t.at(1.0)->x, 1.0);
  EXPECT_NEAR(t.at(1.5)->x, 1.5, 1e-12);
}

TEST(OdometryTimeline, NoPoseFartherThanTheGapFromAnyOdometry) {
  EXPECT_FALSE(OdometryTimeline().at(0.0)) << "no odometry at all";
  const OdometryTimeline t({{10.0, {1, 0, 0}}, {20.0, {2, 0, 0}}}, 0.5);
  EXPECT_DOUBLE_EQ(t.at(9.6)->x, 1.0);   // before the first, within the gap: the first pose
  EXPECT_DOUBLE_EQ(t.at(20.4)->x, 2.0);  // after the last, within the gap: the last pose
  EXPECT_FALSE(t.at(9.4));
  EXPECT_FALSE(t.at(20.6));
  EXPECT_FALSE(t.at(15.0)) << "5 s from both sides of a gap in the odometry";
  EXPECT_NEAR(t.at(10.4)->x, 1.04, 1e-12);
  EXPECT_THROW(OdometryTimeline({}, -1.0), std::invalid_argument);
  EXPECT_THROW(OdometryTimeline({}, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace krp
