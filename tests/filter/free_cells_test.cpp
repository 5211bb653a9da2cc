// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/free_cells.h"

#include <gtest/gtest.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include "mrpt_krp_plugin/filter/seeded_initializer.h"
#include "support/test_maps.h"

namespace krp {
namespace {

constexpr double kMinFreeness = 0.7;

TEST(FreeCells, DescribesOnlyTheMapAndThresholdItWasBuiltFrom) {
  const auto room = test::asymmetricRoom();
  const FreeCells free(room, kMinFreeness);
  EXPECT_EQ(free.cells(), freeCellsOf(room, kMinFreeness));
  EXPECT_FALSE(free.cells().empty());
  EXPECT_TRUE(free.describes(room, kMinFreeness));
  EXPECT_TRUE(free.describes(test::asymmetricRoom(), kMinFreeness)) << "an equal map, another object";
  EXPECT_FALSE(free.describes(room, 0.9)) << "another threshold";
  EXPECT_FALSE(free.describes(test::asymmetricRoom(9.0), kMinFreeness)) << "another size";
  auto changed = room;
  const int cx = static_cast<int>(changed.getSizeX() / 2), cy = static_cast<int>(changed.getSizeY() / 2);
  changed.setCell(cx, cy, 1.0f - changed.getCell(cx, cy));
  EXPECT_FALSE(free.describes(changed, kMinFreeness)) << "one cell flipped";
}

mrpt::obs::CSensoryFrame frameWithScan() {
  mrpt::obs::CSensoryFrame sf;
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->resizeScan(10);
  sf.insert(scan);
  return sf;
}

std::vector<mrpt::math::TPose2D> seededParticles(const mrpt::maps::COccupancyGridMap2D& map,
                                                 std::shared_ptr<const FreeCells> free) {
  Ranking ranking;
  PoseHypothesis h;
  h.pose = {3.0, 2.0, 0.5};
  h.cov.setIdentity();
  h.cov *= 0.01;
  h.confidence = 1.0;
  ranking.hypotheses = {h};
  SeededInitParams p;
  p.uniform_fraction = 0.3;  // enough uniform draws that a wrong cell list would show
  SeededInitializer init([&](const auto&) { return ranking; }, p);
  init.useFreeCells(std::move(free));
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  init.initialize(pf, o, map, frameWithScan());
  std::vector<mrpt::math::TPose2D> out;
  for (const auto& particle : pf.m_particles) out.push_back(particle.d);
  return out;
}

TEST(FreeCells, SeedingFromThemDrawsTheSameParticlesAsReadingTheMap) {
  const auto room = test::asymmetricRoom();
  const auto afresh = seededParticles(room, nullptr);
  ASSERT_FALSE(afresh.empty());
  EXPECT_EQ(seededParticles(room, std::make_shared<const FreeCells>(room, kMinFreeness)), afresh);
  // Cells of another map are not used: the uniform share is drawn from this map's, as without them.
  const auto other = test::twinRooms();
  EXPECT_EQ(seededParticles(room, std::make_shared<const FreeCells>(other, kMinFreeness)), afresh);
  // The maps' cells differ enough that drawing from the wrong ones would show.
  EXPECT_NE(freeCellsOf(other, kMinFreeness), freeCellsOf(room, kMinFreeness));
}

}  // namespace
}  // namespace krp
