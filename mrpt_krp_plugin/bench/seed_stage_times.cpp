// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/seed_stage_times.h"

#include <sstream>

#include "mrpt_krp_plugin/bench/record_groups.h"
#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/common/statistics.h"

namespace krp {
namespace {

/// Every stage, in the order the relocalizer runs them, with its name in the CSV and the table.
struct Stage {
  const char* csv;
  const char* column;
  double RelocalizationTimes::*ms;
};
constexpr Stage kStages[] = {
    {"seed_submap_ms", "submaps and images", &RelocalizationTimes::submap_ms},
    {"seed_classifier_ms", "zone classifier", &RelocalizationTimes::classifier_ms},
    {"seed_keypoints_ms", "keypoint model", &RelocalizationTimes::keypoints_ms},
    {"seed_alignment_ms", "alignment", &RelocalizationTimes::alignment_ms},
    {"seed_verification_ms", "verification", &RelocalizationTimes::verification_ms},
    {"seed_zone_search_ms", "zone search", &RelocalizationTimes::zone_search_ms},
    {"seed_cross_check_ms", "cross-check", &RelocalizationTimes::cross_check_ms},
};

}  // namespace

std::vector<SeedStageSummary> summarizeSeedStages(const std::vector<TrialRecord>& records) {
  std::vector<SeedStageSummary> out;
  const auto timed = [](const TrialRecord& r) { return r.seed_stage_times.has_value(); };
  for (const auto& group : groupByWorldLidarMethod(records, timed)) {
    SeedStageSummary s;
    s.world = group.front()->world;
    s.lidar = group.front()->lidar;
    s.method = group.front()->method;
    s.trials = static_cast<int>(group.size());
    std::vector<double> totals;
    for (const auto* r : group) {
      for (const auto& stage : kStages) s.mean.*stage.ms += (*r->seed_stage_times).*stage.ms;
      s.mean.total_ms += r->seed_stage_times->total_ms;
      totals.push_back(r->seed_stage_times->total_ms);
    }
    for (const auto& stage : kStages) s.mean.*stage.ms /= s.trials;
    s.mean.total_ms /= s.trials;
    s.median_total_ms = median(totals);
    out.push_back(s);
  }
  return out;
}

std::string seedStageTable(const std::vector<SeedStageSummary>& summaries) {
  if (summaries.empty()) return "";
  std::ostringstream o;
  o << "Where the learned relocalizer's time from the first scan goes: the wall time of each stage, mean over "
       "trials in ms (a stage that did not run counts 0, so the stages add up to about the mean total; the zone search "
       "runs only when the keypoints give no credible pose). \"Scan to prior\" above is thread CPU time and "
       "includes drawing the particles.\n\n| world | lidar | method | trials |";
  for (const auto& stage : kStages) o << " " << stage.column << " |";
  o << " total, mean | total, median |\n|---|---|---|---|";
  for (std::size_t i = 0; i < std::size(kStages) + 2; ++i) o << "---|";
  o << "\n";
  for (const auto& s : summaries) {
    o << "| " << s.world << " | " << s.lidar << " | " << s.method << " | " << s.trials << " |";
    for (const auto& stage : kStages) o << " " << formatNumber(s.mean.*stage.ms) << " |";
    o << " " << formatNumber(s.mean.total_ms) << " | " << formatNumber(s.median_total_ms) << " |\n";
  }
  o << "\n";
  return o.str();
}

std::string seedStageCsvHeader() {
  std::string header;
  for (const auto& stage : kStages) header += std::string(",") + stage.csv;
  return header + ",seed_relocalize_ms";
}

std::string seedStageCsvFields(const TrialRecord& record) {
  std::ostringstream o;
  for (const auto& stage : kStages) {
    o << ",";
    if (record.seed_stage_times) o << (*record.seed_stage_times).*stage.ms;
  }
  o << ",";
  if (record.seed_stage_times) o << record.seed_stage_times->total_ms;
  return o.str();
}

}  // namespace krp
