// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/sensor_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/filter/uniform_initializer.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "support/test_maps.h"

namespace krp {
namespace {

/// MRPT's marker for a cache entry not computed yet.
constexpr double kNotComputed = 66.0;

/// Reads MRPT's protected likelihood cache (a pointer to member named through a derived class).
struct LikelihoodCache : mrpt::maps::COccupancyGridMap2D {
  static const std::vector<double>& of(const mrpt::maps::COccupancyGridMap2D& map) {
    return map.*(&LikelihoodCache::m_precomputedLikelihood);
  }
};

/// A model other than the default in every field that shapes a cached value, and in decimation.
SensorModelParams otherModel() {
  SensorModelParams s;
  s.decimation = 2;
  s.std_hit_m = 0.3;
  s.max_corr_distance_m = 0.4;
  s.z_hit = 0.9;
  s.z_random = 0.1;
  return s;
}

TEST(SensorModel, PreparedLikelihoodsAreTheOnesMrptComputesOnDemand) {
  const auto room = test::asymmetricRoom();
  for (const auto& sensor : {SensorModelParams{}, otherModel()}) {
    auto on_demand = room;
    useSensorModel(on_demand, sensor);
    const auto prepared = prepareSensorModelMap(room, sensor);
    Rng rng(3);
    const ScanSimulator sim(lidarProfileByName("omni_12m"));
    const auto scan = sim.simulate(room, mrpt::poses::CPose2D(5.5, 2.0, 0.8), rng);
    for (const auto& at : {mrpt::poses::CPose2D(5.5, 2.0, 0.8), mrpt::poses::CPose2D(3.0, 4.0, -2.0),
                           mrpt::poses::CPose2D(7.6, 1.1, 0.1)}) {
      const mrpt::poses::CPose3D pose(at);
      EXPECT_DOUBLE_EQ(prepared.grid->computeObservationLikelihood(*scan, pose),
                       on_demand.computeObservationLikelihood(*scan, pose));
    }
    EXPECT_EQ(prepared.grid->likelihoodOptions.LF_decimation, static_cast<uint32_t>(sensor.decimation));
  }
}

TEST(SensorModel, PreparationComputesEveryCellAndACopyKeepsThem) {
  const auto room = test::asymmetricRoom();
  const auto prepared = prepareSensorModelMap(room, SensorModelParams{});
  const auto copy = *prepared.grid;  // as MclLocalizer takes it
  const auto& cache = LikelihoodCache::of(copy);
  ASSERT_EQ(cache.size(), static_cast<size_t>(room.getSizeX()) * room.getSizeY());
  // MRPT never caches the last row and column (it treats them as outside the map).
  size_t missing = 0;
  for (unsigned cy = 0; cy + 1 < room.getSizeY(); ++cy)
    for (unsigned cx = 0; cx + 1 < room.getSizeX(); ++cx) missing += cache[cx + cy * room.getSizeX()] == kNotComputed;
  EXPECT_EQ(missing, 0u);
  // Without preparation the cache starts empty (or all not computed).
  auto on_demand = room;
  useSensorModel(on_demand, SensorModelParams{});
  const auto& lazy = LikelihoodCache::of(on_demand);
  EXPECT_TRUE(std::all_of(lazy.begin(), lazy.end(), [](double v) { return v == kNotComputed; }));
}

TEST(SensorModel, AFilterRefusesAMapPreparedForAnotherModel) {
  const auto room = test::asymmetricRoom();
  const auto prepared = prepareSensorModelMap(room, otherModel());
  EXPECT_THROW(MclLocalizer(prepared, std::make_shared<UniformInitializer>(), MclParams{}), std::invalid_argument);
  MclParams matching;
  matching.sensor = otherModel();
  EXPECT_NO_THROW(MclLocalizer(prepared, std::make_shared<UniformInitializer>(), matching));
}

}  // namespace
}  // namespace krp
