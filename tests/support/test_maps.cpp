// SPDX-License-Identifier: BSD-3-Clause
#include "support/test_maps.h"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

#include "mrpt_krp_plugin/sim/floor_plan.h"

namespace krp::test {

namespace {
FloorPlan asymmetricRoomPlan(double w, double h, double res) {
  FloorPlan plan(w + 1.0, h + 1.0, res);
  plan.building(0.5, 0.5, 0.5 + w, 0.5 + h);
  plan.wall(0.5 + 0.3 * w, 0.5, 0.5 + 0.3 * w, 0.5 + 0.4 * h);
  plan.wall(0.5 + 0.3 * w, 0.5 + 0.4 * h, 0.5 + 0.45 * w, 0.5 + 0.4 * h);
  plan.solid(0.5 + 0.75 * w, 0.5 + 0.7 * h, 0.5 + 0.85 * w, 0.5 + 0.9 * h);
  return plan;
}
}  // namespace

mrpt::maps::COccupancyGridMap2D asymmetricRoom(double w, double h, double res) {
  return asymmetricRoomPlan(w, h, res).toGrid();
}

mrpt::maps::COccupancyGridMap2D asymmetricRoomWithPillarsAround(double x, double y, int pillars, double radius_m,
                                                               double pillar_m) {
  auto plan = asymmetricRoomPlan(8.0, 6.0, 0.05);
  for (int i = 0; i < pillars; ++i) {
    const double a = 2.0 * M_PI * i / pillars;
    const double cx = x + radius_m * std::cos(a), cy = y + radius_m * std::sin(a);
    plan.solid(cx - 0.5 * pillar_m, cy - 0.5 * pillar_m, cx + 0.5 * pillar_m, cy + 0.5 * pillar_m);
  }
  return plan.toGrid();
}

namespace {
// The folders this process made, removed when it exits (unless KRP_KEEP_TEST_DIRS is set, to
// look at what a failing test wrote).
class TempDirRegistry {
 public:
  ~TempDirRegistry() {
    if (std::getenv("KRP_KEEP_TEST_DIRS")) return;
    std::error_code ignored;
    for (const auto& d : dirs_) std::filesystem::remove_all(d, ignored);
  }
  void add(const std::filesystem::path& d) { dirs_.push_back(d); }

 private:
  std::vector<std::filesystem::path> dirs_;
};
}  // namespace

std::string tempDir(const std::string& name) {
  static TempDirRegistry registry;
  const auto dir = std::filesystem::temp_directory_path() / ("krp_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  registry.add(dir);
  return dir.string();
}

void writeText(const std::string& path, const std::string& content) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path, std::ios::binary) << content;
}

}  // namespace krp::test
