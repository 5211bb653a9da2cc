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
// The room's walls, its south-west outer corner at (x0 + 0.5, 0.5).
void drawAsymmetricRoom(FloorPlan& plan, double x0, double w, double h) {
  const double left = x0 + 0.5;
  plan.building(left, 0.5, left + w, 0.5 + h);
  plan.wall(left + 0.3 * w, 0.5, left + 0.3 * w, 0.5 + 0.4 * h);
  plan.wall(left + 0.3 * w, 0.5 + 0.4 * h, left + 0.45 * w, 0.5 + 0.4 * h);
  plan.solid(left + 0.75 * w, 0.5 + 0.7 * h, left + 0.85 * w, 0.5 + 0.9 * h);
}

FloorPlan asymmetricRoomPlan(double w, double h, double res) {
  FloorPlan plan(w + 1.0, h + 1.0, res);
  drawAsymmetricRoom(plan, 0.0, w, h);
  return plan;
}

constexpr double kDefaultRoomW = 8.0, kDefaultRoomH = 6.0, kDefaultRoomRes = 0.05;
}  // namespace

mrpt::maps::COccupancyGridMap2D asymmetricRoom(double w, double h, double res) {
  return asymmetricRoomPlan(w, h, res).toGrid();
}

mrpt::maps::COccupancyGridMap2D asymmetricRoomWithPillarsAround(double x, double y, int pillars, double radius_m,
                                                               double pillar_m) {
  auto plan = asymmetricRoomPlan(kDefaultRoomW, kDefaultRoomH, kDefaultRoomRes);
  for (int i = 0; i < pillars; ++i) {
    const double a = 2.0 * M_PI * i / pillars;
    const double cx = x + radius_m * std::cos(a), cy = y + radius_m * std::sin(a);
    plan.solid(cx - 0.5 * pillar_m, cy - 0.5 * pillar_m, cx + 0.5 * pillar_m, cy + 0.5 * pillar_m);
  }
  return plan.toGrid();
}

double twinRoomsShiftM(double gap_m) { return kDefaultRoomW + 1.0 + gap_m; }

mrpt::maps::COccupancyGridMap2D twinRooms(double gap_m) {
  FloorPlan plan(kDefaultRoomW + 1.0 + twinRoomsShiftM(gap_m), kDefaultRoomH + 1.0, kDefaultRoomRes);
  drawAsymmetricRoom(plan, 0.0, kDefaultRoomW, kDefaultRoomH);
  drawAsymmetricRoom(plan, twinRoomsShiftM(gap_m), kDefaultRoomW, kDefaultRoomH);
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
