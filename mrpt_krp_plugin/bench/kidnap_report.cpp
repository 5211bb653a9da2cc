// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/kidnap_report.h"

#include <cmath>
#include <sstream>

#include "mrpt_krp_plugin/bench/record_groups.h"
#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/common/statistics.h"

namespace krp {
namespace {

std::string percent(double rate) { return std::isfinite(rate) ? formatNumber(100.0 * rate) + " %" : "-"; }

}  // namespace

std::vector<KidnapSummary> summarizeKidnaps(const std::vector<TrialRecord>& records) {
  std::vector<KidnapSummary> out;
  for (const auto& g : groupByWorldLidarMethod(records, [](const TrialRecord& r) { return r.kidnap_step >= 0; })) {
    KidnapSummary s{g.front()->world, g.front()->lidar, g.front()->method};
    std::vector<double> detect, recover, cpu;
    int tracking = 0, recovered = 0, wrong = 0;
    for (const auto* r : g) {
      const auto& o = r->kidnap;
      ++s.trials;
      // Detection and recovery only mean something for a filter that was tracking when the
      // robot was carried off.
      if (!o.tracking_before) continue;
      ++tracking;
      wrong += o.confident_but_wrong ? 1 : 0;
      if (o.updates_to_detect > 0) detect.push_back(o.updates_to_detect);
      if (o.recovered) {
        ++recovered;
        recover.push_back(o.updates_to_recover);
        cpu.push_back(o.cpu_to_recover_s);
      }
    }
    s.tracking_before = tracking;
    s.tracking_before_rate = static_cast<double>(tracking) / s.trials;
    const double n = tracking > 0 ? tracking : std::nan("");
    s.detected_rate = static_cast<double>(detect.size()) / n;
    s.recovered_rate = recovered / n;
    s.confident_wrong_rate = wrong / n;
    s.median_updates_to_detect = median(detect);
    s.median_updates_to_recover = median(recover);
    s.median_cpu_to_recover_s = median(cpu);
    out.push_back(s);
  }
  return out;
}

std::string kidnapSection(const std::vector<KidnapSummary>& summaries, int kidnap_step) {
  if (summaries.empty()) return "";
  std::ostringstream o;
  o << "## Kidnap mid-run\n\nAt update " << kidnap_step + 1 << " (step " << kidnap_step
    << ") the robot is carried to the start of a second trial, with no odometry for the carry; every method runs "
       "with the filter's kidnap detector on (three updates in a row whose scan fit at the mean is too low re-run "
       "the method's initializer). \"Tracking before\": within tolerance at the update before the kidnap; the "
       "columns after it are over those trials only, since detecting and recovering mean nothing for a filter "
       "that was lost already. \"Detected\": the detector fired after the kidnap; updates are counted from the "
       "kidnap (1 = the first scan after it). \"Recovered\": within tolerance again at some update and every "
       "later one. Medians over the trials that detected or recovered.\n\n"
    << "| world | lidar | method | trials | tracking before | of those: detected | median updates to detect | "
       "recovered | median updates to recover | median CPU s to recover | confident-wrong at the end |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& s : summaries)
    o << "| " << s.world << " | " << s.lidar << " | " << s.method << " | " << s.trials << " | "
      << s.tracking_before << " (" << percent(s.tracking_before_rate) << ") | " << percent(s.detected_rate) << " | " << formatNumber(s.median_updates_to_detect)
      << " | " << percent(s.recovered_rate) << " | " << formatNumber(s.median_updates_to_recover) << " | "
      << formatNumber(s.median_cpu_to_recover_s) << " | " << percent(s.confident_wrong_rate) << " |\n";
  return o.str() + "\n";
}

}  // namespace krp
