// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/single_scan_sweep.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <filesystem>

#include "mrpt_krp_plugin/common/input_error.h"
#include "support/test_maps.h"

namespace krp {
namespace {

std::vector<RawlogStep> stepsWithScans(std::size_t n) {
  std::vector<RawlogStep> steps;
  for (std::size_t i = 0; i < n; ++i) {
    auto scan = mrpt::obs::CObservation2DRangeScan::Create();
    scan->resizeScan(3);
    steps.push_back(makeRawlogStep(mrpt::poses::CPose2D(), scan));
  }
  return steps;
}

// Answers, call by call: localized near the truth, localized 3 m off, not localized with a
// right best, nothing at all.
HypothesisSource scriptedSource(const std::vector<mrpt::math::TPose2D>& truth) {
  auto call = std::make_shared<std::size_t>(0);
  return [call, truth](const mrpt::obs::CObservation2DRangeScan&) {
    const std::size_t i = (*call)++;
    Ranking r;
    PoseHypothesis h;
    h.confidence = 0.9;
    h.origin = i % 8 == 0 ? PoseOrigin::kKeypoints : PoseOrigin::kMatcher;
    switch (i % 4) {
      case 0: h.pose = {truth[i].x + 0.1, truth[i].y, truth[i].phi + 0.05}; r.localized = true; break;
      case 1: h.pose = {truth[i].x + 3.0, truth[i].y, truth[i].phi}; r.localized = true; break;
      case 2: h.pose = truth[i]; r.reason = "ambiguous"; break;
      default: r.reason = "nothing fits"; return r;
    }
    r.hypotheses.push_back(h);
    return r;
  };
}

TEST(SingleScanSweep, CountsRightAndConfidentlyWrongAnswersAgainstTheTruth) {
  std::vector<mrpt::math::TPose2D> truth;
  for (int i = 0; i < 8; ++i) truth.emplace_back(i, 2.0 * i, 0.1 * i);
  const auto records = sweepSingleScans(scriptedSource(truth), stepsWithScans(8), truth, 1, ConvergenceCriteria{}, nullptr);
  ASSERT_EQ(records.size(), 8u);
  EXPECT_NEAR(records[1].error_xy_m, 3.0, 1e-9);
  EXPECT_NEAR(records[0].error_phi_deg, 0.05 * 180.0 / M_PI, 1e-9);
  EXPECT_FALSE(records[3].best.has_value());
  EXPECT_EQ(records[3].reason, "nothing fits");
  const auto s = summarizeSweep(records);
  EXPECT_EQ(s.scans, 8u);
  EXPECT_EQ(s.localized, 4u);
  EXPECT_EQ(s.localized_right, 2u);
  EXPECT_EQ(s.localized_wrong, 2u);
  EXPECT_EQ(s.best_right, 4u);  // steps 0 and 2 of each four
  EXPECT_TRUE(s.has_truth);
  // Localized answers are 0.1 m (steps 0, 4) and 3 m (steps 1, 5) off: the median is the mean of
  // the two middles, as everywhere in the project (common/statistics.h).
  EXPECT_NEAR(s.median_error_xy_m, 1.55, 1e-9);
  EXPECT_NE(sweepSummaryText(s).find("localized but wrong: 2 (25 %)"), std::string::npos) << sweepSummaryText(s);
  // Only step 0's answer came from the keypoint model.
  EXPECT_TRUE(records[0].best_from_keypoints);
  EXPECT_FALSE(records[4].best_from_keypoints);
  EXPECT_EQ(s.localized_from_keypoints, 1u);
  EXPECT_NE(sweepSummaryText(s).find("localized from the keypoint model: 1 (12.5 %)"), std::string::npos);
  const auto csv = sweepCsv(records);
  EXPECT_NE(csv.find(",best_right,best_from,reason\n"), std::string::npos);
  EXPECT_NE(csv.find(",keypoints,\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",,nothing fits\n"), std::string::npos) << csv;
}

TEST(SingleScanSweep, StrideSkipsScansAndTruthMustMatchTheSteps) {
  std::vector<mrpt::math::TPose2D> truth(10);
  const auto records = sweepSingleScans(scriptedSource(truth), stepsWithScans(10), {}, 3, ConvergenceCriteria{}, nullptr);
  ASSERT_EQ(records.size(), 4u);  // steps 0, 3, 6, 9
  EXPECT_EQ(records[3].step, 9u);
  EXPECT_LT(records[0].error_xy_m, 0.0);  // no truth, no error
  EXPECT_FALSE(summarizeSweep(records).has_truth);
  EXPECT_THROW(sweepSingleScans(scriptedSource(truth), stepsWithScans(10), std::vector<mrpt::math::TPose2D>(4), 1,
                                ConvergenceCriteria{}, nullptr),
               InputError);
  EXPECT_THROW(sweepSingleScans(scriptedSource(truth), stepsWithScans(10), {}, 0, ConvergenceCriteria{}, nullptr), InputError);
}

TEST(SingleScanSweep, CsvHasOneRowPerScanAndThePngIsWritten) {
  std::vector<mrpt::math::TPose2D> truth;
  for (int i = 0; i < 4; ++i) truth.emplace_back(1.0 + i, 1.0, 0.0);
  const auto records = sweepSingleScans(scriptedSource(truth), stepsWithScans(4), truth, 1, ConvergenceCriteria{}, nullptr);
  const auto csv = sweepCsv(records);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  const auto dir = test::tempDir("sweep_png");
  writeSweepPng(test::asymmetricRoom(), records, truth, dir + "/sweep.png");
  EXPECT_GT(std::filesystem::file_size(dir + "/sweep.png"), 100u);
}

}  // namespace
}  // namespace krp
