// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/scaling_report.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "mrpt_krp_plugin/bench/line_plot.h"
#include "mrpt_krp_plugin/bench/record_groups.h"
#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/common/statistics.h"

namespace krp {

std::vector<ScalingPoint> scalingPoints(const std::vector<TrialRecord>& records) {
  std::vector<ScalingPoint> out;
  for (const auto& recs : groupByWorldLidarMethod(records)) {
    ScalingPoint p{recs.front()->world, recs.front()->lidar, recs.front()->method};
    std::vector<double> particles, first_cpu, cpu;
    int converged = 0;
    for (const auto* r : recs) {
      p.free_area_m2 = r->free_area_m2;
      particles.push_back(static_cast<double>(r->outcome.initial_particles));
      if (!r->updates.empty()) first_cpu.push_back(r->updates.front().cpu_s);
      if (r->outcome.converged) ++converged, cpu.push_back(r->outcome.cpu_to_convergence_s);
    }
    p.median_initial_particles = median(particles);
    p.median_first_update_cpu_s = median(first_cpu);
    p.median_cpu_to_convergence_s = median(cpu);
    p.success_rate = static_cast<double>(converged) / static_cast<double>(recs.size());
    out.push_back(p);
  }
  std::sort(out.begin(), out.end(), [](const ScalingPoint& a, const ScalingPoint& b) {
    return std::tie(a.method, a.lidar, a.free_area_m2) < std::tie(b.method, b.lidar, b.free_area_m2);
  });
  return out;
}

std::string scalingSection(const std::vector<ScalingPoint>& points, const std::string& plot_file) {
  std::set<std::string> worlds;
  for (const auto& p : points) worlds.insert(p.world);
  if (worlds.size() < 2) return "";
  std::ostringstream o;
  o << "## Cost as the free area grows\n\nPer method, what localizing from nothing costs on each world: the "
       "particles it starts with, the CPU of its first update (the initializer, relocalization included, and the "
       "first filter update), and the CPU to convergence (median over converged trials).\n\n"
    << "| method | lidar | world | free area m^2 | initial particles | first update CPU s | CPU to convergence s | "
       "success |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& p : points)
    o << "| " << p.method << " | " << p.lidar << " | " << p.world << " | " << formatNumber(p.free_area_m2, 5) << " | "
      << formatNumber(p.median_initial_particles, 6) << " | " << formatNumber(p.median_first_update_cpu_s) << " | "
      << formatNumber(p.median_cpu_to_convergence_s) << " | " << formatNumber(100.0 * p.success_rate) << " % |\n";
  o << "\n![cost by free area](" << plot_file << ")\n\n";
  return o.str();
}

void writeScalingPlot(const std::vector<ScalingPoint>& points, const std::string& png_path) {
  std::map<std::string, PlotSeries> series;
  for (const auto& p : points) {
    auto& s = series[p.method + ", " + p.lidar];
    s.label = p.method + ", " + p.lidar;
    s.x.push_back(p.free_area_m2);
    s.y.push_back(p.median_first_update_cpu_s);
  }
  std::vector<PlotSeries> lines;
  for (auto& [name, s] : series) lines.push_back(std::move(s));
  LinePlotParams lp;
  lp.log_y = true;
  writeLinePlot(png_path, "First-update CPU by free area (median)", "free area m^2", "CPU s", lines, lp);
}

}  // namespace krp
