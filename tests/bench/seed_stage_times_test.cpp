// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/seed_stage_times.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace krp {
namespace {

TrialRecord record(const std::string& method, std::optional<RelocalizationTimes> times) {
  TrialRecord r;
  r.world = "office_two_zone", r.lidar = "omni_12m", r.method = method;
  r.seed_stage_times = times;
  return r;
}

RelocalizationTimes times(double keypoints_ms, double zone_search_ms, double total_ms) {
  RelocalizationTimes t;
  t.keypoints_ms = keypoints_ms;
  t.zone_search_ms = zone_search_ms;
  t.total_ms = total_ms;
  return t;
}

TEST(SeedStageTimes, MeansEveryStageOverTheTimedTrialsOfAMethod) {
  // The zone search ran in one trial of two: its mean counts the other as 0.
  const std::vector<TrialRecord> records = {record("seeded", times(8.0, 0.0, 10.0)), record("uniform-mcl", std::nullopt),
                                            record("seeded", times(10.0, 20.0, 34.0)),
                                            record("seeded", std::nullopt)};
  const auto summaries = summarizeSeedStages(records);
  ASSERT_EQ(summaries.size(), 1u) << "only methods with stage times";
  const auto& s = summaries.front();
  EXPECT_EQ(s.method, "seeded");
  EXPECT_EQ(s.trials, 2);
  EXPECT_DOUBLE_EQ(s.mean.keypoints_ms, 9.0);
  EXPECT_DOUBLE_EQ(s.mean.zone_search_ms, 10.0);
  EXPECT_DOUBLE_EQ(s.mean.cross_check_ms, 0.0);
  EXPECT_DOUBLE_EQ(s.mean.total_ms, 22.0);
  EXPECT_DOUBLE_EQ(s.median_total_ms, 22.0);

  const auto table = seedStageTable(summaries);
  EXPECT_NE(table.find("| office_two_zone | omni_12m | seeded | 2 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| 9 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| 22 | 22 |"), std::string::npos) << table;
  EXPECT_TRUE(seedStageTable(summarizeSeedStages({record("amcl-kld", std::nullopt)})).empty());
}

TEST(SeedStageTimes, CsvFieldsMatchTheHeaderAndStayEmptyWithoutTimes) {
  const auto header = seedStageCsvHeader();
  const auto timed = seedStageCsvFields(record("seeded", times(8.5, 0.0, 10.0)));
  const auto untimed = seedStageCsvFields(record("amcl-kld", std::nullopt));
  const auto commas = [](const std::string& s) { return std::count(s.begin(), s.end(), ','); };
  EXPECT_EQ(commas(timed), commas(header));
  EXPECT_EQ(untimed, std::string(static_cast<size_t>(commas(header)), ','));
  EXPECT_NE(header.find(",seed_keypoints_ms,"), std::string::npos);
  EXPECT_NE(timed.find(",8.5,"), std::string::npos) << timed;
  EXPECT_EQ(timed.substr(timed.rfind(',')), ",10");
}

}  // namespace
}  // namespace krp
