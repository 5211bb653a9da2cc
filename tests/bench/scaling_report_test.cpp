// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/scaling_report.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_maps.h"

namespace krp {
namespace {

TrialRecord trial(const std::string& world, double area, const std::string& method, size_t particles, double first_cpu,
                  bool converged, double cpu) {
  TrialRecord r;
  r.world = world, r.lidar = "omni_12m", r.method = method, r.free_area_m2 = area;
  r.outcome.initial_particles = particles;
  r.outcome.converged = converged;
  r.outcome.cpu_to_convergence_s = cpu;
  UpdateRecord u;
  u.cpu_s = first_cpu;
  r.updates.push_back(u);
  return r;
}

TEST(ScalingReport, OnePointPerMethodAndWorldOrderedByArea) {
  const std::vector<TrialRecord> records = {
      trial("big", 2000, "uniform-mcl", 80000, 4.0, true, 8.0), trial("small", 500, "uniform-mcl", 20000, 1.0, true, 2.0),
      trial("small", 500, "uniform-mcl", 20000, 3.0, false, -1), trial("big", 2000, "global-matcher", 632, 2.0, true, 2.0),
      trial("small", 500, "global-matcher", 632, 0.5, true, 0.5)};
  const auto points = scalingPoints(records);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points[0].method, "global-matcher");
  EXPECT_EQ(points[0].world, "small");
  EXPECT_EQ(points[3].world, "big");
  EXPECT_EQ(points[2].world, "small");
  EXPECT_DOUBLE_EQ(points[2].median_first_update_cpu_s, 2.0);  // median of 1 and 3
  EXPECT_DOUBLE_EQ(points[2].median_cpu_to_convergence_s, 2.0);  // converged trials only
  EXPECT_DOUBLE_EQ(points[2].success_rate, 0.5);
  const auto md = scalingSection(points, "scaling.png");
  EXPECT_NE(md.find("| uniform-mcl | omni_12m | big | 2000 | 80000 | 4 | 8 | 100 % |"), std::string::npos) << md;
  const auto dir = test::tempDir("scaling_plot");
  writeScalingPlot(points, dir + "/scaling.png");
  EXPECT_GT(std::filesystem::file_size(dir + "/scaling.png"), 100u);
}

TEST(ScalingReport, NoSectionForOneWorld) {
  EXPECT_TRUE(scalingSection(scalingPoints({trial("only", 100, "uniform-mcl", 4000, 0.1, true, 0.1)}), "x.png").empty());
}

}  // namespace
}  // namespace krp
