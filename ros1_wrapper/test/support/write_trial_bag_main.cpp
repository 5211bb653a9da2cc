// SPDX-License-Identifier: BSD-3-Clause
// Writes a simulated kidnap in a sim world as a ROS 1 bag plus its ground truth, for the
// krp-localize --bag app test.   krp_ros_write_trial_bag WORLD.yaml SEED OUT.bag OUT_truth.txt
#include <fstream>
#include <iostream>

#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "support/trial_bag.h"

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: krp_ros_write_trial_bag WORLD.yaml SEED OUT.bag OUT_truth.txt\n";
    return 2;
  }
  const auto world = krp::readWorld(argv[1]);
  const auto map = krp::loadOccupancyMap(world.map_path);
  krp::TrialParams tp;
  tp.steps = 10;
  const auto trial = krp::generateTrial(*map.grid, world.lidar(world.default_lidar_profile), tp, std::stoull(argv[2]));
  krp::ros1::test::writeTrialBag(trial, argv[3]);
  std::ofstream gt(argv[4]);
  gt.precision(9);
  for (size_t i = 0; i < trial.truth.size(); ++i)
    gt << i << " " << trial.truth[i].x << " " << trial.truth[i].y << " " << trial.truth[i].phi << "\n";
  std::cout << "wrote " << argv[3] << " (" << trial.scans.size() << " scans)\n";
  return 0;
}
