// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/matcher_speed.h"

#include <cmath>
#include <memory>
#include <sstream>

#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/common/statistics.h"
#include "mrpt_krp_plugin/common/thread_cpu_time.h"
#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/filter/see_through.h"

namespace krp {
namespace {

constexpr double kMsPerS = 1000.0;

/// What one search answered, to hold the two settings to the same answer.
struct Answer {
  std::vector<MatchSolution> solutions;
  long long nodes = 0;
  long long stopped_early = 0;
  double cpu_s = 0.0;

  bool sameSearchAs(const Answer& o) const {
    if (nodes != o.nodes || solutions.size() != o.solutions.size()) return false;
    for (size_t i = 0; i < solutions.size(); ++i) {
      const auto &a = solutions[i], &b = o.solutions[i];
      if (a.score != b.score || a.pose.x != b.pose.x || a.pose.y != b.pose.y || a.pose.phi != b.pose.phi) return false;
    }
    return true;
  }
};

/// One setting of stop_bound_early: its matcher and the guard searching with it.
struct Searcher {
  std::shared_ptr<const CorrelativeMatcher> matcher;
  LookAlikeGuard guard;

  Searcher(const mrpt::maps::COccupancyGridMap2D& map, CorrelativeMatcherParams params, bool stop_early,
           const LookAlikeGuardParams& guard_params)
      : matcher(std::make_shared<CorrelativeMatcher>(map, withStopping(params, stop_early))), guard(matcher, guard_params) {}

  static CorrelativeMatcherParams withStopping(CorrelativeMatcherParams p, bool stop_early) {
    p.stop_bound_early = stop_early;
    return p;
  }
  Answer wholeMap(const mrpt::obs::CObservation2DRangeScan& scan) const {
    Answer a;
    const double t0 = threadCpuSeconds();
    a.solutions = matcher->match(scan);
    a.cpu_s = threadCpuSeconds() - t0;
    return counted(a);
  }
  Answer lookAlike(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& tracked,
                   const SeeThroughPenalty::Scan& see_through) const {
    Answer a;
    const double t0 = threadCpuSeconds();
    const auto found = guard.lookAlike(scan, tracked, {}, &see_through);
    a.cpu_s = threadCpuSeconds() - t0;
    if (found) a.solutions.push_back({found->pose, found->score});
    return counted(a);
  }
  Answer counted(Answer a) const {
    a.nodes = matcher->lastNodesScored();
    a.stopped_early = matcher->lastNodesStoppedEarly();
    return a;
  }
};

/// Per-scan answers of both settings for one kind of search.
struct Tally {
  std::vector<double> all_ms, stopping_ms, ratio, nodes;
  double all_s = 0.0, stopping_s = 0.0;
  long long nodes_total = 0, stopped_total = 0;
  int differing = 0;

  void add(const Answer& all, const Answer& stopping) {
    all_ms.push_back(all.cpu_s * kMsPerS);
    stopping_ms.push_back(stopping.cpu_s * kMsPerS);
    if (stopping.cpu_s > 0.0) ratio.push_back(all.cpu_s / stopping.cpu_s);
    nodes.push_back(static_cast<double>(stopping.nodes));
    all_s += all.cpu_s;
    stopping_s += stopping.cpu_s;
    nodes_total += stopping.nodes;
    stopped_total += stopping.stopped_early;
    if (!all.sameSearchAs(stopping)) ++differing;
  }
  MatcherSpeedRow row(const std::string& search) const {
    MatcherSpeedRow r;
    r.search = search;
    r.scans = static_cast<int>(all_ms.size());
    r.median_ms_reading_all = median(all_ms);
    r.median_ms_stopping = median(stopping_ms);
    r.median_ratio = ratio.empty() ? 0.0 : median(ratio);
    r.total_ratio = stopping_s > 0.0 ? all_s / stopping_s : 0.0;
    r.median_nodes = median(nodes);
    r.share_stopped_early = nodes_total > 0 ? static_cast<double>(stopped_total) / static_cast<double>(nodes_total) : 0.0;
    r.differing = differing;
    return r;
  }
};

}  // namespace

std::vector<MatcherSpeedRow> measureMatcherSpeed(const mrpt::maps::COccupancyGridMap2D& map, const LidarProfile& lidar,
                                                 const MatcherSpeedParams& params, const std::function<void()>& progress) {
  const Searcher reading_all(map, params.matcher, false, params.guard);
  const Searcher stopping(map, params.matcher, true, params.guard);
  const MclParams filter;  // the guard charges see-through beams as the filter does
  const SeeThroughPenalty see_through(map, filter.sensor, filter.see_through);
  TrialParams trial_params = params.trial;
  trial_params.steps = 0;  // the first scan is all a search sees
  Tally whole_map, look_alike;
  for (int i = 0; i < params.scans; ++i) {
    const auto trial = generateTrial(map, lidar, trial_params, params.seed + static_cast<uint64_t>(i));
    const auto& scan = *trial.scans.front();
    const auto& truth = trial.truth.front();
    const auto charge = see_through.forScan(scan);
    // Whichever runs second finds the caches warm: the settings take turns going first.
    const bool all_first = i % 2 == 0;
    Answer a, b;
    if (all_first) {
      a = reading_all.wholeMap(scan);
      b = stopping.wholeMap(scan);
    } else {
      b = stopping.wholeMap(scan);
      a = reading_all.wholeMap(scan);
    }
    whole_map.add(a, b);
    if (all_first) {
      a = reading_all.lookAlike(scan, truth, charge);
      b = stopping.lookAlike(scan, truth, charge);
    } else {
      b = stopping.lookAlike(scan, truth, charge);
      a = reading_all.lookAlike(scan, truth, charge);
    }
    look_alike.add(a, b);
    if (progress) progress();
  }
  return {whole_map.row("whole map"), look_alike.row("look-alike check")};
}

std::string matcherSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows) {
  std::ostringstream md;
  md << "| search | scans | median ms, every return read | median ms, bounds stop early | speed-up (median of per-scan "
        "ratios) | speed-up (total) | median nodes | nodes stopped early | scans answered differently |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    md << "| " << r.search << " | " << r.scans << " | " << formatNumber(r.median_ms_reading_all) << " | "
       << formatNumber(r.median_ms_stopping) << " | " << formatNumber(r.median_ratio) << "x | " << formatNumber(r.total_ratio)
       << "x | " << std::llround(r.median_nodes) << " | " << formatNumber(100.0 * r.share_stopped_early) << " % | "
       << r.differing << " |\n";
  return md.str();
}

}  // namespace krp
