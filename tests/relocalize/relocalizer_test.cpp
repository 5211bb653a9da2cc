// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/relocalize/relocalizer.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "mrpt_krp_plugin/sim/world.h"

namespace krp {
namespace {

const std::string kModels = std::string(KRP_SOURCE_DIR) + "/models/office_two_zone";
const std::string kWorld = std::string(KRP_SOURCE_DIR) + "/sim_worlds/office_two_zone/office_two_zone.world.yaml";

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The shipped office models were trained for omni_12m (360 deg, 12 m) on a 0.05 m map.
TEST(Relocalizer, RefusesScansFromAnotherLidar) {
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  const Relocalizer relocalizer(kModels, *map.grid);
  const auto trial = generateTrial(*map.grid, world.lidar("omni_12m"), TrialParams{}, 5);
  const mrpt::poses::CPose2D pose(trial.truth[0]);
  Rng rng(1);
  const auto own = ScanSimulator(lidarProfileByName("omni_12m")).simulate(*map.grid, pose, rng);
  EXPECT_EQ(messageOf([&] { relocalizer.relocalize(*own); }), "");
  for (const char* other : {"safety_270", "lds01"}) {
    const auto scan = ScanSimulator(lidarProfileByName(other)).simulate(*map.grid, pose, rng);
    const auto message = messageOf([&] { relocalizer.relocalize(*scan); });
    EXPECT_NE(message.find("trained for lidar 'omni_12m'"), std::string::npos) << other << ": " << message;
  }
}

TEST(Relocalizer, RefusesAMapOfAnotherCellSize) {
  const auto map = loadOccupancyMap(readWorld(kWorld).map_path);
  mrpt::maps::COccupancyGridMap2D coarse;
  coarse.setSize(map.grid->getXMin(), map.grid->getXMax(), map.grid->getYMin(), map.grid->getYMax(), 0.1f);
  const auto message = messageOf([&] { Relocalizer(kModels, coarse); });
  EXPECT_NE(message.find("trained on a map of 0.05"), std::string::npos) << message;
}

}  // namespace
}  // namespace krp
