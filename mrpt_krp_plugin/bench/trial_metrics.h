// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/filter/filter_spread.h"
#include "mrpt_krp_plugin/filter/mcl_localizer.h"

namespace krp {

/// When a filter counts as localized, and when it counts as "confident".
struct ConvergenceCriteria {
  double max_error_xy_m = 0.5;       ///< mean within this of the truth [m]
  double max_error_phi_deg = 10.0;   ///< and within this heading [deg]
  /// The filter's reported spread below these reads as confident. Its covariance includes a
  /// look-alike place the guard found (MclEstimate::ambiguous_with) and is widened for a scan the
  /// map explains too little of (MclEstimate::scan_unexplained), so such an estimate is not
  /// confident however tight its particles are.
  ConcentrationThresholds confident;
};

/// An error within the criteria's position and heading tolerance.
bool withinTolerance(double error_xy_m, double error_phi_deg, const ConvergenceCriteria& criteria);

/// One filter update against the truth.
struct UpdateRecord {
  double error_xy_m = 0.0;
  double error_phi_deg = 0.0;
  FilterSpread spread;       ///< of the filter's reported covariance
  bool ambiguous = false;    ///< the filter reported a look-alike place (MclEstimate::ambiguous_with)
  double fit_fraction = -1.0;    ///< scan returns explained at the mean (MclEstimate::fit_fraction; -1: not measured)
  bool scan_unexplained = false;  ///< the guard widened the covariance for too few explained returns
  std::size_t particles = 0;
  double cpu_s = 0.0;
  int look_alike_searches = 0;          ///< MclEstimate::look_alike_searches
  double look_alike_search_cpu_s = 0.0;  ///< their CPU, part of cpu_s [s]
  int look_alike_searches_unfinished = 0;  ///< MclEstimate::look_alike_searches_unfinished
  bool look_alike_unverified = false;      ///< MclEstimate::look_alike_unverified
  double distance_m = 0.0;   ///< true distance travelled up to this update [m]
  bool kidnap_detected = false;  ///< the filter's kidnap detector fired at this update
};

UpdateRecord makeUpdateRecord(const MclEstimate& e, const mrpt::math::TPose2D& truth, double distance_m);

/// What the bench reports per trial.
struct TrialOutcome {
  bool converged = false;            ///< within tolerance at some update and every later one
  int updates_to_convergence = -1;   ///< 1 = localized from the first scan; -1 if never
  double distance_to_convergence_m = -1.0;
  double cpu_to_convergence_s = -1.0;
  std::size_t initial_particles = 0;
  double mean_particles = 0.0;
  double particle_updates_to_convergence = -1.0;  ///< sum of particles over updates up to convergence
  double final_error_xy_m = 0.0;
  double final_error_phi_deg = 0.0;
  bool confident_but_wrong = false;  ///< at the last update: spread small, pose outside tolerance
  bool confident_and_right = false;  ///< at the last update: spread small, pose within tolerance
  double total_cpu_s = 0.0;
  int look_alike_searches = 0;          ///< the guard's whole-map searches over the trial
  double look_alike_search_cpu_s = 0.0;  ///< their CPU, part of total_cpu_s [s]
  int look_alike_searches_unfinished = 0;  ///< of those, the ones out of budget with nothing found
};

TrialOutcome evaluateTrial(const std::vector<UpdateRecord>& updates, const ConvergenceCriteria& criteria);

/// How a filter fared when the robot was carried away mid-run (the kidnap at `kidnap_step`).
struct KidnapOutcome {
  bool tracking_before = false;   ///< within tolerance at the update before the kidnap
  int updates_to_detect = -1;     ///< 1 = the detector fired at the first update after the kidnap; -1 never
  bool recovered = false;         ///< within tolerance again at some update after it, and every later one
  int updates_to_recover = -1;    ///< counted from the kidnap (1 = the first update after it); -1 if never
  double cpu_to_recover_s = -1.0; ///< localization CPU from the kidnap to recovery [s]
  bool confident_but_wrong = false;  ///< at the last update
};

/// Throws std::invalid_argument for a kidnap step outside 1 .. updates-1.
KidnapOutcome evaluateKidnap(const std::vector<UpdateRecord>& updates, std::size_t kidnap_step,
                             const ConvergenceCriteria& criteria);

}  // namespace krp
