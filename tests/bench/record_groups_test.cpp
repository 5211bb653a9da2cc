// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/record_groups.h"

#include <gtest/gtest.h>

namespace krp {
namespace {

TrialRecord record(const std::string& world, const std::string& method, int trial) {
  TrialRecord r;
  r.world = world, r.lidar = "omni_12m", r.method = method, r.trial = trial;
  return r;
}

TEST(RecordGroups, GroupsInFirstAppearanceOrderAndKeepsOnlyWhatIsAsked) {
  const std::vector<TrialRecord> records = {record("b", "m1", 0), record("a", "m1", 0), record("b", "m2", 0),
                                            record("b", "m1", 1), record("a", "m1", 1)};
  const auto groups = groupByWorldLidarMethod(records);
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].front()->world, "b");
  EXPECT_EQ(groups[0].size(), 2u);
  EXPECT_EQ(groups[0][1]->trial, 1);
  EXPECT_EQ(groups[1].front()->world, "a");
  EXPECT_EQ(groups[2].front()->method, "m2");
  const auto firsts = groupByWorldLidarMethod(records, [](const TrialRecord& r) { return r.trial == 0; });
  ASSERT_EQ(firsts.size(), 3u);
  EXPECT_EQ(firsts[0].size(), 1u);
  EXPECT_TRUE(groupByWorldLidarMethod(records, [](const TrialRecord&) { return false; }).empty());
}

}  // namespace
}  // namespace krp
