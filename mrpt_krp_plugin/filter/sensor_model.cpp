// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/sensor_model.h"

#include <mrpt/maps/CSimplePointsMap.h>

namespace krp {

void useSensorModel(mrpt::maps::COccupancyGridMap2D& map, const SensorModelParams& sensor) {
  auto& lo = map.likelihoodOptions;
  lo.likelihoodMethod = mrpt::maps::COccupancyGridMap2D::lmLikelihoodField_Thrun;
  lo.LF_decimation = static_cast<uint32_t>(sensor.decimation);
  lo.LF_stdHit = static_cast<float>(sensor.std_hit_m);
  lo.LF_maxCorrsDistance = static_cast<float>(sensor.max_corr_distance_m);
  lo.LF_zHit = static_cast<float>(sensor.z_hit);
  lo.LF_zRandom = static_cast<float>(sensor.z_random);
  lo.LF_useSquareDist = false;
  lo.enableLikelihoodCache = true;
}

void fillLikelihoodField(mrpt::maps::COccupancyGridMap2D& map, const SensorModelParams& sensor) {
  useSensorModel(map, sensor);
  // One point at every cell's centre, weighed at the identity pose, makes MRPT compute and cache
  // each cell's likelihood; every point must count, hence no decimation for this call.
  mrpt::maps::CSimplePointsMap centres;
  centres.reserve(static_cast<size_t>(map.getSizeX()) * map.getSizeY());
  for (unsigned cy = 0; cy < map.getSizeY(); ++cy)
    for (unsigned cx = 0; cx < map.getSizeX(); ++cx) centres.insertPointFast(map.idx2x(cx), map.idx2y(cy), 0.0f);
  map.likelihoodOptions.LF_decimation = 1;
  map.computeLikelihoodField_Thrun(&centres, nullptr);
  map.likelihoodOptions.LF_decimation = static_cast<uint32_t>(sensor.decimation);
}

SensorModelMap prepareSensorModelMap(const mrpt::maps::COccupancyGridMap2D& map, const SensorModelParams& sensor) {
  auto grid = std::make_shared<mrpt::maps::COccupancyGridMap2D>(map);
  fillLikelihoodField(*grid, sensor);
  return {grid, sensor};
}

}  // namespace krp
