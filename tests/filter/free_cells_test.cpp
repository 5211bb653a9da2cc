// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/free_cells.h"

#include <gtest/gtest.h>

#include "support/test_maps.h"

namespace krp {
namespace {

constexpr double kMinFreeness = 0.7;

TEST(FreeCells, DescribesOnlyTheMapAndThresholdItWasBuiltFrom) {
  const auto room = test::asymmetricRoom();
  const FreeCells free(room, kMinFreeness);
  EXPECT_EQ(free.cells(), freeCellsOf(room, kMinFreeness));
  EXPECT_FALSE(free.cells().empty());
  EXPECT_TRUE(free.describes(room, kMinFreeness));
  EXPECT_TRUE(free.describes(test::asymmetricRoom(), kMinFreeness)) << "an equal map, another object";
  EXPECT_FALSE(free.describes(room, 0.9)) << "another threshold";
  EXPECT_FALSE(free.describes(test::asymmetricRoom(9.0), kMinFreeness)) << "another size";
  auto changed = room;
  const int cx = static_cast<int>(changed.getSizeX() / 2), cy = static_cast<int>(changed.getSizeY() / 2);
  changed.setCell(cx, cy, 1.0f - changed.getCell(cx, cy));
  EXPECT_FALSE(free.describes(changed, kMinFreeness)) << "one cell flipped";
}

}  // namespace
}  // namespace krp
