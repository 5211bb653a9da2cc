// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/path_ambiguity_report.h"

#include <sstream>

#include "mrpt_krp_plugin/bench/record_groups.h"
#include "mrpt_krp_plugin/bench/report_format.h"

namespace krp {
namespace {

void add(PathAmbiguitySplit::Counts& c, const TrialOutcome& o) {
  ++c.trials;
  c.success += o.converged ? 1 : 0;
  c.confident_wrong += o.confident_but_wrong ? 1 : 0;
  c.confident_right += o.confident_and_right ? 1 : 0;
}

std::string share(int part, int whole) {
  if (whole == 0) return "-";
  return std::to_string(part) + "/" + std::to_string(whole) + " (" + formatNumber(100.0 * part / whole) + " %)";
}

// success, confident but wrong, confident and right over one verdict's trials
std::string cells(const PathAmbiguitySplit::Counts& c) {
  return share(c.success, c.trials) + " | " + share(c.confident_wrong, c.trials) + " | " + share(c.confident_right, c.trials);
}

}  // namespace

std::vector<PathAmbiguitySplit> splitByPathAmbiguity(const std::vector<TrialRecord>& records) {
  std::vector<PathAmbiguitySplit> out;
  const auto checked = [](const TrialRecord& r) { return r.path.verdict != PathVerdict::not_checked; };
  for (const auto& g : groupByWorldLidarMethod(records, checked)) {
    PathAmbiguitySplit s{g.front()->world, g.front()->lidar, g.front()->method, {}, {}, {}};
    for (const auto* r : g) {
      switch (r->path.verdict) {
        case PathVerdict::told_apart: add(s.told_apart, r->outcome); break;
        case PathVerdict::ambiguous: add(s.ambiguous, r->outcome); break;
        case PathVerdict::misleading: add(s.misleading, r->outcome); break;
        case PathVerdict::not_checked: break;
      }
    }
    out.push_back(s);
  }
  return out;
}

std::string pathAmbiguitySection(const std::vector<PathAmbiguitySplit>& splits, const PathAmbiguityParams& params) {
  if (splits.empty()) return "";
  std::ostringstream o;
  o << "## What the scans allow: trials whose path another place explains as well\n\n"
    << "Once every method has run, each trial is checked against its truth. The places weighed are those (up to "
    << params.max_places
    << ", at least the matcher's exclusion distance from the truth and from one another) whose matcher score on "
       "the first scan is within "
    << formatNumber(params.first_scan_margin)
    << " of the truth's, and each place where a method ended away from the truth, moved back to where a twin "
       "robot would have had to start (one within the exclusion distance of the truth or of a place already "
       "weighed is not weighed again; so the more methods a run compares, the more places it weighs). Each is driven along the truth's own path, and weighed against it scan after "
       "scan with the filter's sensor model (and its see-through penalty when on). The truth is weighed as the "
       "places are, so that neither side is held nearer its best fit than the other: it starts "
    << formatNumber(params.truth_offset_steps)
    << " of a step off its exact pose; on the first scan every side is first moved to its best pose within "
    << formatNumber(params.tracking.first_scan_search_m) << " m / " << formatNumber(params.tracking.first_scan_search_deg)
    << " deg, and on every scan it is re-fitted on a "
    << formatNumber(params.tracking.refine_step_m * 100.0) << " cm / "
    << formatNumber(params.tracking.refine_step_deg) << " deg grid and then on "
    << params.tracking.finer_refinements
    << " grids of half the last one's steps. *Told apart*: the truth leads every such place by at least "
    << formatNumber(params.decisive_log_ratio)
    << " nats over the whole path. *Ambiguous*: some place stays within that, so the trial's scans cannot say "
       "which of the two the robot is at, and a method that is right and confident there is right by luck. "
       "*Misleading*: some place explains the path better than the truth by as much (unmapped clutter). Columns "
       "`path_*` of `trials.csv` hold each trial's verdict, the places weighed (and how many of them were where "
       "methods ended), the truth's lead over the closest, that place's distance and where it came from "
       "(`first_scan` or the method that ended there). A verdict of *told apart* can still be optimistic: a place "
       "that neither fits the first scan nor held any method is not weighed.\n\n"
    << "| world | lidar | trials | told apart | ambiguous | misleading |\n|---|---|---|---|---|---|\n";
  std::string last_pair;
  for (const auto& s : splits) {
    const std::string pair = s.world + "/" + s.lidar;
    if (pair == last_pair) continue;  // the verdicts are the trial's, the same for every method
    last_pair = pair;
    const int n = s.told_apart.trials + s.ambiguous.trials + s.misleading.trials;
    o << "| " << s.world << " | " << s.lidar << " | " << n << " | " << share(s.told_apart.trials, n) << " | "
      << share(s.ambiguous.trials, n) << " | " << share(s.misleading.trials, n) << " |\n";
  }
  o << "\nEach method's success / confident but wrong / confident and right, within each verdict's trials:\n\n"
    << "| world | lidar | method | told apart: success | confident-wrong | confident-right | ambiguous: success | "
       "confident-wrong | confident-right | misleading: success | confident-wrong | confident-right |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& s : splits)
    o << "| " << s.world << " | " << s.lidar << " | " << s.method << " | " << cells(s.told_apart) << " | "
      << cells(s.ambiguous) << " | " << cells(s.misleading) << " |\n";
  o << "\n";
  return o.str();
}

}  // namespace krp
