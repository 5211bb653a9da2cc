// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/sim/scan_simulator.h"

#include <algorithm>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

namespace {
// MRPT marches max_range/resolution steps; with steps of `ray_step_cells` the reach is
// that fraction of max range, and a small margin covers rounding of the step count.
constexpr double kReachMargin = 1.05;
}  // namespace

ScanSimulator::ScanSimulator(LidarProfile profile, ScanSimulatorParams params)
    : profile_(std::move(profile)), params_(params) {
  if (profile_.beams < 2) throw InputError("lidar profile '" + profile_.name + "'", "needs at least 2 beams");
  if (!(profile_.max_range_m > 0)) throw InputError("lidar profile '" + profile_.name + "'", "max range must be > 0");
  if (!(params_.ray_step_cells > 0 && params_.ray_step_cells <= 1.0))
    throw InputError("scan simulator", "ray_step_cells must be in (0, 1]");
}

mrpt::obs::CObservation2DRangeScan::Ptr ScanSimulator::simulate(const mrpt::maps::COccupancyGridMap2D& world,
                                                                const mrpt::poses::CPose2D& robot_pose,
                                                                Rng& rng) const {
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->sensorLabel = "LIDAR";
  scan->aperture = static_cast<float>(profile_.mrptAperture());
  scan->rightToLeft = true;
  scan->sensorPose = mrpt::poses::CPose3D(profile_.mount_x_m, 0, 0, 0, 0, 0);
  scan->maxRange = static_cast<float>(profile_.max_range_m * kReachMargin / params_.ray_step_cells);

  const double saved_step = mrpt::maps::COccupancyGridMap2D::RAYTRACE_STEP_SIZE_IN_CELL_UNITS;
  mrpt::maps::COccupancyGridMap2D::RAYTRACE_STEP_SIZE_IN_CELL_UNITS = params_.ray_step_cells;
  world.laserScanSimulator(*scan, robot_pose, static_cast<float>(params_.free_threshold),
                           static_cast<size_t>(profile_.beams), 0.0f, 1, 0.0f);
  mrpt::maps::COccupancyGridMap2D::RAYTRACE_STEP_SIZE_IN_CELL_UNITS = saved_step;

  scan->maxRange = static_cast<float>(profile_.max_range_m);
  for (size_t i = 0; i < scan->getScanSize(); ++i) {
    float r = scan->getScanRange(i);
    bool valid = scan->getScanRangeValidity(i) && r < profile_.max_range_m;
    if (valid && rng.bernoulli(profile_.dropout_probability)) valid = false;
    if (valid) r = static_cast<float>(std::max(0.0, rng.normal(r, profile_.range_noise_std_m)));
    else r = scan->maxRange;
    scan->setScanRange(i, r);
    scan->setScanRangeValidity(i, valid);
  }
  return scan;
}

}  // namespace krp
