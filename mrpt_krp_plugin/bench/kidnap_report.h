// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/bench/bench_runner.h"

namespace krp {

/// Per world, lidar and method over the kidnapped trials: how often the filter tracked before
/// the kidnap, and of those trials how often it noticed the kidnap and recovered, and how many
/// updates and how much CPU that took. Rates are NaN when no trial was tracking.
struct KidnapSummary {
  std::string world, lidar, method;
  int trials = 0;
  int tracking_before = 0;  ///< trials within tolerance just before the kidnap; the rates below are over these
  double tracking_before_rate = 0.0;
  double detected_rate = 0.0;
  double median_updates_to_detect = 0.0;  ///< over detected trials (NaN for none)
  double recovered_rate = 0.0;
  double median_updates_to_recover = 0.0;  ///< over recovered trials
  double median_cpu_to_recover_s = 0.0;    ///< over recovered trials
  double confident_wrong_rate = 0.0;       ///< at the last update
};

/// Summaries of the records with a kidnap, in the order their groups first appear.
std::vector<KidnapSummary> summarizeKidnaps(const std::vector<TrialRecord>& records);

/// The Markdown section (heading, what the columns mean, the table); empty without kidnaps.
std::string kidnapSection(const std::vector<KidnapSummary>& summaries, int kidnap_step);

}  // namespace krp
