// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/matcher_speed.h"

#include <gtest/gtest.h>

#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "support/test_maps.h"

namespace krp {
namespace {

// Each comparison runs both settings on the same scans; the settings that must not change an
// answer do not, and the tables hold one row per search.
TEST(MatcherSpeed, ComparesEachSettingOnTheSameScans) {
  const auto map = test::twinRooms();
  MatcherSpeedParams params;
  params.scans = 3;
  const auto rows = measureMatcherSpeed(map, lidarProfileByName("omni_12m"), params);
  EXPECT_EQ(rows.scans, 3);
  ASSERT_EQ(rows.stop_early.size(), 2u);
  ASSERT_EQ(rows.wall_headings.size(), 2u);
  ASSERT_EQ(rows.warm_start.size(), 2u);
  for (const auto& r : rows.stop_early) {
    EXPECT_EQ(r.scans, 3) << r.search;
    EXPECT_EQ(r.differing, 0) << r.search << ": bounds that stop early change the cost, not the search";
  }
  for (const auto& r : rows.warm_start) {
    EXPECT_EQ(r.scans, 3) << r.search;
    EXPECT_EQ(r.scores_differing, 0) << r.search;
    EXPECT_LE(r.median_nodes, r.median_nodes_baseline) << r.search << ": a warm start prunes more, never less";
    EXPECT_GT(r.median_nodes, 0.0) << r.search;
  }
  // Over every heading the warm-started whole-map search is the stop-early one (same settings).
  EXPECT_DOUBLE_EQ(rows.warm_start[0].median_nodes, rows.stop_early[0].median_nodes);

  const std::string warm = warmStartSpeedMarkdown(rows.warm_start);
  EXPECT_NE(warm.find("| whole map, every heading | 3 |"), std::string::npos) << warm;
  EXPECT_NE(warm.find("| whole map, wall headings | 3 |"), std::string::npos) << warm;
  EXPECT_NE(warm.find("scores differ | places differ |"), std::string::npos) << warm;
  const std::string walls = wallHeadingSpeedMarkdown(rows.wall_headings);
  EXPECT_NE(walls.find("best answer differs | any answer differs |"), std::string::npos) << walls;
}

}  // namespace
}  // namespace krp
