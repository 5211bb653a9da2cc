// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/bench/bench_runner.h"

namespace krp {

/// One method on one world and lidar, as the free area grows: what localizing from nothing costs.
struct ScalingPoint {
  std::string world, lidar, method;
  double free_area_m2 = 0.0;
  double median_initial_particles = 0.0;
  double median_first_update_cpu_s = 0.0;  ///< initialization (relocalization included) + first filter update
  double median_cpu_to_convergence_s = 0.0;  ///< over converged trials (NaN for none)
  double success_rate = 0.0;
};

/// Points per (world, lidar, method), ordered by method, then free area.
std::vector<ScalingPoint> scalingPoints(const std::vector<TrialRecord>& records);

/// The Markdown section (table and the plot's image link); empty with fewer than two worlds.
std::string scalingSection(const std::vector<ScalingPoint>& points, const std::string& plot_file);

/// Median first-update CPU against free area, one line per method and lidar (log y), as PNG.
void writeScalingPlot(const std::vector<ScalingPoint>& points, const std::string& png_path);

}  // namespace krp
