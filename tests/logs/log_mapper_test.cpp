// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/logs/log_mapper.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "support/test_maps.h"

namespace krp {
namespace {

struct PosedScans {
  std::vector<RawlogStep> steps;
  std::vector<mrpt::math::TPose2D> poses;
};

PosedScans scansOf(const mrpt::maps::COccupancyGridMap2D& room) {
  PosedScans out;
  Rng rng(3);
  const ScanSimulator sim(lidarProfileByName("omni_12m"));
  for (const mrpt::math::TPose2D p : {mrpt::math::TPose2D(1.5, 1.5, 0.3), mrpt::math::TPose2D(6.0, 2.0, 2.0),
                                      mrpt::math::TPose2D(5.0, 5.5, -1.0), mrpt::math::TPose2D(1.5, 5.0, -0.5)}) {
    out.steps.push_back(makeRawlogStep(mrpt::poses::CPose2D(), sim.simulate(room, mrpt::poses::CPose2D(p), rng)));
    out.poses.push_back(p);
  }
  return out;
}

bool occupiedNear(const mrpt::maps::COccupancyGridMap2D& map, double x, double y, int cells) {
  const int cx = map.x2idx(x), cy = map.y2idx(y);
  for (int dy = -cells; dy <= cells; ++dy)
    for (int dx = -cells; dx <= cells; ++dx) {
      const int ix = cx + dx, iy = cy + dy;
      if (ix < 0 || iy < 0 || ix >= int(map.getSizeX()) || iy >= int(map.getSizeY())) continue;
      if (map.getCell(ix, iy) < 1.0 - CellClassParams{}.min_occupied_occupancy) return true;
    }
  return false;
}

TEST(LogMapper, RebuildsTheWallsTheScansSaw) {
  const auto room = test::asymmetricRoom();
  const auto log = scansOf(room);
  const auto built = mapFromPosedScans(log.steps, log.poses);
  const CellClassParams classes;
  int occupied = 0, on_a_wall = 0;
  for (unsigned cy = 0; cy < built.getSizeY(); ++cy)
    for (unsigned cx = 0; cx < built.getSizeX(); ++cx) {
      if (built.getCell(cx, cy) >= 1.0 - classes.min_occupied_occupancy) continue;
      ++occupied;
      on_a_wall += occupiedNear(room, built.idx2x(cx), built.idx2y(cy), 2) ? 1 : 0;
    }
  ASSERT_GT(occupied, 200);
  EXPECT_GT(on_a_wall, 0.97 * occupied) << on_a_wall << " of " << occupied << " occupied cells lie on a wall of the room";
  EXPECT_GT(freeAreaM2(built), 0.8 * freeAreaM2(room));
}

TEST(LogMapper, EveryOtherScanLeavesTheOthersOut) {
  const auto room = test::asymmetricRoom();
  const auto log = scansOf(room);
  LogMapperParams even;
  even.every = 2;
  LogMapperParams odd = even;
  odd.first = 1;
  EXPECT_LT(freeAreaM2(mapFromPosedScans(log.steps, log.poses, even)), freeAreaM2(mapFromPosedScans(log.steps, log.poses)));
  EXPECT_NE(countFreeCells(mapFromPosedScans(log.steps, log.poses, even)), countFreeCells(mapFromPosedScans(log.steps, log.poses, odd)));
}

TEST(LogMapper, RefusesMismatchedPosesAndBadParameters) {
  const auto room = test::asymmetricRoom();
  auto log = scansOf(room);
  LogMapperParams p;
  p.first = 10;
  EXPECT_THROW(mapFromPosedScans(log.steps, log.poses, p), InputError);
  p = {};
  p.every = 0;
  EXPECT_THROW(mapFromPosedScans(log.steps, log.poses, p), InputError);
  p = {};
  p.resolution_m = std::nan("");
  EXPECT_THROW(mapFromPosedScans(log.steps, log.poses, p), InputError);
  log.poses.pop_back();
  EXPECT_THROW(mapFromPosedScans(log.steps, log.poses), InputError);
}

}  // namespace
}  // namespace krp
