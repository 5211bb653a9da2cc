// SPDX-License-Identifier: BSD-3-Clause
#include "guard_cost_note.h"

#include <gtest/gtest.h>

namespace krp::ros1 {
namespace {

TEST(GuardCostNote, SpeaksOnlyWhenTheSearchesOutlastTheScanInterval) {
  EXPECT_FALSE(guardCostNote(0.030, 1, 0.040, 1).has_value()) << "fits between two scans";
  EXPECT_FALSE(guardCostNote(0.040, 1, 0.040, 1).has_value()) << "exactly fits";
  EXPECT_FALSE(guardCostNote(0.0, 0, 0.040, 1).has_value()) << "no search this update";
  EXPECT_FALSE(guardCostNote(0.084, 1, 0.0, 1).has_value()) << "first scan: no interval yet";
  EXPECT_FALSE(guardCostNote(0.084, 1, -0.1, 1).has_value()) << "stamps going backwards (bag replay)";
  const auto note = guardCostNote(0.084, 2, 0.040, 3);
  ASSERT_TRUE(note.has_value());
  EXPECT_NE(note->find("2 search(es) took 84 ms"), std::string::npos) << *note;
  EXPECT_NE(note->find("the 40 ms between scans"), std::string::npos) << *note;
  EXPECT_NE(note->find("look_alike_recheck_every_updates (3)"), std::string::npos) << *note;
}

TEST(GuardCostNote, AnUnverifiedPoseNamesTheBudgetAndWhetherTheCovarianceIsWidened) {
  const auto widened = unverifiedPoseNote(4000000, true);
  EXPECT_NE(widened.find("look_alike_max_search_nodes (4000000)"), std::string::npos) << widened;
  EXPECT_NE(widened.find("the published covariance is widened"), std::string::npos) << widened;
  const auto flagged = unverifiedPoseNote(1, false);
  EXPECT_NE(flagged.find("look_alike_max_search_nodes (1)"), std::string::npos) << flagged;
  EXPECT_NE(flagged.find("is not widened"), std::string::npos) << flagged;
}

TEST(GuardCostNote, APoseUnverifiedWhileASearchRunsSaysSoAndNamesThePerUpdateBudget) {
  const auto widened = pendingSearchNote(500000, true);
  EXPECT_NE(widened.find("one is running"), std::string::npos) << widened;
  EXPECT_NE(widened.find("look_alike_max_nodes_per_update (500000)"), std::string::npos) << widened;
  EXPECT_NE(widened.find("the published covariance is widened"), std::string::npos) << widened;
  EXPECT_NE(pendingSearchNote(7, false).find("is not widened"), std::string::npos);
}

}  // namespace
}  // namespace krp::ros1
