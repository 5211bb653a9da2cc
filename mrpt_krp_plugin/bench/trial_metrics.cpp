// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/trial_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace krp {

bool withinTolerance(double error_xy_m, double error_phi_deg, const ConvergenceCriteria& c) {
  return error_xy_m <= c.max_error_xy_m && error_phi_deg <= c.max_error_phi_deg;
}

UpdateRecord makeUpdateRecord(const MclEstimate& e, const mrpt::math::TPose2D& truth, double distance_m) {
  UpdateRecord r;
  r.error_xy_m = std::hypot(e.mean.x - truth.x, e.mean.y - truth.y);
  r.error_phi_deg = std::abs(mrpt::math::wrapToPi(e.mean.phi - truth.phi)) * 180.0 / M_PI;
  r.spread = filterSpread(e.cov);
  r.ambiguous = e.ambiguous_with.has_value();
  r.fit_fraction = e.fit_fraction;
  r.scan_unexplained = e.scan_unexplained;
  r.particles = e.particles;
  r.cpu_s = e.cpu_s;
  r.look_alike_searches = e.look_alike_searches;
  r.look_alike_search_cpu_s = e.look_alike_search_cpu_s;
  r.look_alike_searches_unfinished = e.look_alike_searches_unfinished;
  r.look_alike_unverified = e.look_alike_unverified;
  r.distance_m = distance_m;
  r.kidnap_detected = e.kidnap_detected;
  return r;
}

TrialOutcome evaluateTrial(const std::vector<UpdateRecord>& u, const ConvergenceCriteria& c) {
  TrialOutcome o;
  if (u.empty()) return o;
  auto within = [&](const UpdateRecord& r) { return withinTolerance(r.error_xy_m, r.error_phi_deg, c); };
  // The first update from which every later update stays within tolerance.
  int first = -1;
  for (int i = static_cast<int>(u.size()) - 1; i >= 0 && within(u[i]); --i) first = i;
  o.initial_particles = u.front().particles;
  double sum_particles = 0.0;
  for (const auto& r : u) {
    sum_particles += static_cast<double>(r.particles);
    o.total_cpu_s += r.cpu_s;
    o.look_alike_searches += r.look_alike_searches;
    o.look_alike_search_cpu_s += r.look_alike_search_cpu_s;
    o.look_alike_searches_unfinished += r.look_alike_searches_unfinished;
  }
  o.mean_particles = sum_particles / static_cast<double>(u.size());
  if (first >= 0) {
    o.converged = true;
    o.updates_to_convergence = first + 1;
    o.distance_to_convergence_m = u[first].distance_m;
    o.cpu_to_convergence_s = 0.0;
    o.particle_updates_to_convergence = 0.0;
    for (int i = 0; i <= first; ++i) {
      o.cpu_to_convergence_s += u[i].cpu_s;
      o.particle_updates_to_convergence += static_cast<double>(u[i].particles);
    }
  }
  const auto& last = u.back();
  o.final_error_xy_m = last.error_xy_m;
  o.final_error_phi_deg = last.error_phi_deg;
  const bool confident = isConcentrated(last.spread, c.confident);
  o.confident_but_wrong = confident && !within(last);
  o.confident_and_right = confident && within(last);
  return o;
}

KidnapOutcome evaluateKidnap(const std::vector<UpdateRecord>& u, std::size_t kidnap_step, const ConvergenceCriteria& c) {
  if (kidnap_step == 0 || kidnap_step >= u.size())
    throw std::invalid_argument("kidnap step " + std::to_string(kidnap_step) + " outside 1.." + std::to_string(u.size() - 1));
  KidnapOutcome k;
  const auto& before = u[kidnap_step - 1];
  k.tracking_before = withinTolerance(before.error_xy_m, before.error_phi_deg, c);
  for (std::size_t i = kidnap_step; i < u.size() && k.updates_to_detect < 0; ++i)
    if (u[i].kidnap_detected) k.updates_to_detect = static_cast<int>(i - kidnap_step) + 1;
  const std::vector<UpdateRecord> after(u.begin() + static_cast<std::ptrdiff_t>(kidnap_step), u.end());
  const TrialOutcome o = evaluateTrial(after, c);
  k.recovered = o.converged;
  k.updates_to_recover = o.updates_to_convergence;
  k.cpu_to_recover_s = o.cpu_to_convergence_s;
  k.confident_but_wrong = o.confident_but_wrong;
  return k;
}

}  // namespace krp
