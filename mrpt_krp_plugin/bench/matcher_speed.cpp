// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/matcher_speed.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <utility>

#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/statistics.h"
#include "mrpt_krp_plugin/common/thread_cpu_time.h"
#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/filter/see_through.h"
#include "mrpt_krp_plugin/submap/wall_axes.h"

namespace krp {
namespace {

constexpr double kMsPerS = 1000.0;

/// What one search answered, to hold the two settings to the same answer.
struct Answer {
  std::vector<MatchSolution> solutions;
  long long nodes = 0;
  long long stopped_early = 0;
  double cpu_s = 0.0;

  bool sameSearchAs(const Answer& o) const { return nodes == o.nodes && sameAnswerAs(o); }
  bool sameAnswerAs(const Answer& o) const {
    return solutions.size() == o.solutions.size() && sameSolutions(o, solutions.size());
  }
  /// The best solution (or the lack of one) is the same.
  bool sameBestAs(const Answer& o) const {
    return solutions.empty() == o.solutions.empty() && sameSolutions(o, std::min<size_t>(1, solutions.size()));
  }
  /// As many solutions, scoring the same one by one (where they stand aside).
  bool sameScoresAs(const Answer& o) const {
    if (solutions.size() != o.solutions.size()) return false;
    for (size_t i = 0; i < solutions.size(); ++i)
      if (solutions[i].score != o.solutions[i].score) return false;
    return true;
  }
  bool sameSolutions(const Answer& o, size_t count) const {
    for (size_t i = 0; i < count; ++i) {
      const auto &a = solutions[i], &b = o.solutions[i];
      if (a.score != b.score || a.pose.x != b.pose.x || a.pose.y != b.pose.y || a.pose.phi != b.pose.phi) return false;
    }
    return true;
  }
};

/// One setting of stop_bound_early, of the wall-heading window, of warm_start_later_solutions and
/// of roots_across_headings: its matcher and the guard searching with it.
struct Searcher {
  std::shared_ptr<const CorrelativeMatcher> matcher;
  LookAlikeGuard guard;
  MatchRequest whole_map;  ///< the defaults, with the setting's window

  Searcher(const mrpt::maps::COccupancyGridMap2D& map, CorrelativeMatcherParams params, bool stop_early,
           LookAlikeGuardParams guard_params, double wall_heading_window_deg, bool warm_start = true,
           bool roots_across_headings = true)
      : matcher(std::make_shared<CorrelativeMatcher>(
            map, withSettings(params, stop_early, warm_start, roots_across_headings))),
        guard(matcher, withWindow(guard_params, wall_heading_window_deg)) {
    whole_map.wall_heading_window_deg = wall_heading_window_deg;
  }

  static CorrelativeMatcherParams withSettings(CorrelativeMatcherParams p, bool stop_early, bool warm_start,
                                               bool roots_across_headings) {
    p.stop_bound_early = stop_early;
    p.warm_start_later_solutions = warm_start;
    p.roots_across_headings = roots_across_headings;
    return p;
  }
  static LookAlikeGuardParams withWindow(LookAlikeGuardParams p, double window_deg) {
    p.wall_heading_window_deg = window_deg;
    return p;
  }
  Answer wholeMap(const mrpt::obs::CObservation2DRangeScan& scan) const {
    Answer a;
    const double t0 = threadCpuSeconds();
    a.solutions = matcher->match(scan, whole_map);
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
  /// The two settings must search alike (same nodes), not only answer alike.
  bool same_nodes = true;
  std::vector<double> baseline_ms, variant_ms, ratio, nodes, baseline_nodes;
  double baseline_s = 0.0, variant_s = 0.0;
  long long nodes_total = 0, stopped_total = 0;
  int differing = 0, best_differing = 0, scores_differing = 0;

  void add(const Answer& baseline, const Answer& variant) {
    baseline_ms.push_back(baseline.cpu_s * kMsPerS);
    variant_ms.push_back(variant.cpu_s * kMsPerS);
    if (variant.cpu_s > 0.0) ratio.push_back(baseline.cpu_s / variant.cpu_s);
    nodes.push_back(static_cast<double>(variant.nodes));
    baseline_nodes.push_back(static_cast<double>(baseline.nodes));
    baseline_s += baseline.cpu_s;
    variant_s += variant.cpu_s;
    nodes_total += variant.nodes;
    stopped_total += variant.stopped_early;
    if (same_nodes ? !baseline.sameSearchAs(variant) : !baseline.sameAnswerAs(variant)) ++differing;
    if (!baseline.sameBestAs(variant)) ++best_differing;
    if (!baseline.sameScoresAs(variant)) ++scores_differing;
  }
  MatcherSpeedRow row(const std::string& search) const {
    MatcherSpeedRow r;
    r.search = search;
    r.scans = static_cast<int>(baseline_ms.size());
    r.median_ms_baseline = median(baseline_ms);
    r.median_ms_variant = median(variant_ms);
    r.median_ratio = ratio.empty() ? 0.0 : median(ratio);
    r.total_ratio = variant_s > 0.0 ? baseline_s / variant_s : 0.0;
    r.median_nodes = median(nodes);
    r.median_nodes_baseline = median(baseline_nodes);
    r.share_stopped_early = nodes_total > 0 ? static_cast<double>(stopped_total) / static_cast<double>(nodes_total) : 0.0;
    r.differing = differing;
    r.best_differing = best_differing;
    r.scores_differing = scores_differing;
    return r;
  }
};

/// Runs `search` with both searchers, `a_first` saying which goes first (whichever runs second
/// finds the caches warm, so the callers take turns).
template <typename Search>
std::pair<Answer, Answer> sideBySide(const Searcher& a, const Searcher& b, bool a_first, const Search& search) {
  Answer x, y;
  if (a_first) {
    x = search(a);
    y = search(b);
  } else {
    y = search(b);
    x = search(a);
  }
  return {x, y};
}

}  // namespace

MatcherSpeedRows measureMatcherSpeed(const mrpt::maps::COccupancyGridMap2D& map, const LidarProfile& lidar,
                                     const MatcherSpeedParams& params, const std::function<void()>& progress) {
  if (!MatchRequest::validWallHeadingWindow(params.wall_heading_window_deg) || params.wall_heading_window_deg == 0.0)
    throw InputError("wall-heading window", "must be above 0 and at most 45 deg");
  const Searcher reading_all(map, params.matcher, false, params.guard, 0.0);
  const Searcher stopping(map, params.matcher, true, params.guard, 0.0);
  const Searcher windowed(map, params.matcher, true, params.guard, params.wall_heading_window_deg);
  const Searcher cold(map, params.matcher, true, params.guard, 0.0, false);
  const Searcher cold_windowed(map, params.matcher, true, params.guard, params.wall_heading_window_deg, false);
  const Searcher per_heading(map, params.matcher, true, params.guard, 0.0, true, false);
  const Searcher per_heading_windowed(map, params.matcher, true, params.guard, params.wall_heading_window_deg, true, false);
  const MclParams filter;  // the guard charges see-through beams as the filter does
  const SeeThroughPenalty see_through(map, filter.sensor, filter.see_through);
  TrialParams trial_params = params.trial;
  trial_params.steps = 0;  // the first scan is all a search sees
  MatcherSpeedRows rows;
  Tally whole_map, look_alike, whole_map_windowed, look_alike_windowed, warm_every, warm_windowed, across_every,
      across_windowed;
  whole_map_windowed.same_nodes = look_alike_windowed.same_nodes = false;  // fewer headings, fewer nodes
  warm_every.same_nodes = warm_windowed.same_nodes = false;                // a warm start prunes more
  across_every.same_nodes = across_windowed.same_nodes = false;            // so does an earlier best
  for (int i = 0; i < params.scans; ++i) {
    const auto trial = generateTrial(map, lidar, trial_params, params.seed + static_cast<uint64_t>(i));
    const auto& scan = *trial.scans.front();
    const auto& truth = trial.truth.front();
    const auto charge = see_through.forScan(scan);
    ++rows.scans;
    if (const auto centres = windowed.matcher->wallAlignedHeadings(scan, windowed.whole_map); !centres.empty()) {
      ++rows.narrowed_scans;
      const double nearest = nearestHeading(centres, truth.phi);
      rows.max_heading_error_deg =
          std::max(rows.max_heading_error_deg, std::abs(mrpt::math::wrapToPi(nearest - truth.phi)) * 180.0 / M_PI);
    }
    const bool first = i % 2 == 0;
    const auto whole = [&](const Searcher& s) { return s.wholeMap(scan); };
    const auto check = [&](const Searcher& s) { return s.lookAlike(scan, truth, charge); };
    const auto [all_whole, stopping_whole] = sideBySide(reading_all, stopping, first, whole);
    whole_map.add(all_whole, stopping_whole);
    const auto [all_check, stopping_check] = sideBySide(reading_all, stopping, first, check);
    look_alike.add(all_check, stopping_check);
    const auto [every_whole, windowed_whole] = sideBySide(stopping, windowed, first, whole);
    whole_map_windowed.add(every_whole, windowed_whole);
    const auto [every_check, windowed_check] = sideBySide(stopping, windowed, first, check);
    look_alike_windowed.add(every_check, windowed_check);
    const auto [cold_whole, warm_whole] = sideBySide(cold, stopping, first, whole);
    warm_every.add(cold_whole, warm_whole);
    const auto [cold_windowed_whole, warm_windowed_whole] = sideBySide(cold_windowed, windowed, first, whole);
    warm_windowed.add(cold_windowed_whole, warm_windowed_whole);
    const auto [per_heading_whole, across_whole] = sideBySide(per_heading, stopping, first, whole);
    across_every.add(per_heading_whole, across_whole);
    const auto [per_heading_windowed_whole, across_windowed_whole] =
        sideBySide(per_heading_windowed, windowed, first, whole);
    across_windowed.add(per_heading_windowed_whole, across_windowed_whole);
    if (progress) progress();
  }
  rows.stop_early = {whole_map.row("whole map"), look_alike.row("look-alike check")};
  rows.wall_headings = {whole_map_windowed.row("whole map"), look_alike_windowed.row("look-alike check")};
  rows.warm_start = {warm_every.row("whole map, every heading"), warm_windowed.row("whole map, wall headings")};
  rows.across_headings = {across_every.row("whole map, every heading"),
                          across_windowed.row("whole map, wall headings")};
  return rows;
}

std::string matcherSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows) {
  std::ostringstream md;
  md << "| search | scans | median ms, every return read | median ms, bounds stop early | speed-up (median of per-scan "
        "ratios) | speed-up (total) | median nodes | nodes stopped early | scans answered differently |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    md << "| " << r.search << " | " << r.scans << " | " << formatNumber(r.median_ms_baseline) << " | "
       << formatNumber(r.median_ms_variant) << " | " << formatNumber(r.median_ratio) << "x | " << formatNumber(r.total_ratio)
       << "x | " << std::llround(r.median_nodes) << " | " << formatNumber(100.0 * r.share_stopped_early) << " % | "
       << r.differing << " |\n";
  return md.str();
}

namespace {
/// Rows compared in times and node counts, their last two columns the answers that differ:
/// `headers` names the columns after "search | scans", `counts` gives a row's two counts.
std::string comparisonMarkdown(const std::vector<MatcherSpeedRow>& rows, const std::string& headers,
                               const std::function<std::pair<int, int>(const MatcherSpeedRow&)>& counts) {
  std::ostringstream md;
  md << "| search | scans | " << headers << " |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const auto [first, second] = counts(r);
    md << "| " << r.search << " | " << r.scans << " | " << formatNumber(r.median_ms_baseline) << " | "
       << formatNumber(r.median_ms_variant) << " | " << formatNumber(r.median_ratio) << "x | " << formatNumber(r.total_ratio)
       << "x | " << std::llround(r.median_nodes_baseline) << " | " << std::llround(r.median_nodes) << " | " << first
       << " | " << second << " |\n";
  }
  return md.str();
}
}  // namespace

std::string wallHeadingSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows) {
  return comparisonMarkdown(rows,
                            "median ms, every heading | median ms, wall headings | speed-up (median of per-scan "
                            "ratios) | speed-up (total) | median nodes, every heading | median nodes, wall headings | "
                            "best answer differs | any answer differs",
                            [](const MatcherSpeedRow& r) { return std::pair{r.best_differing, r.differing}; });
}

std::string warmStartSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows) {
  return comparisonMarkdown(rows,
                            "median ms, each solution from min_score | median ms, later solutions warm-started | "
                            "speed-up (median of per-scan ratios) | speed-up (total) | median nodes, from min_score | "
                            "median nodes, warm-started | scores differ | places differ",
                            [](const MatcherSpeedRow& r) { return std::pair{r.scores_differing, r.differing}; });
}

std::string acrossHeadingsSpeedMarkdown(const std::vector<MatcherSpeedRow>& rows) {
  return comparisonMarkdown(rows,
                            "median ms, heading after heading | median ms, roots across headings | speed-up (median "
                            "of per-scan ratios) | speed-up (total) | median nodes, heading after heading | median "
                            "nodes, across headings | scores differ | places differ",
                            [](const MatcherSpeedRow& r) { return std::pair{r.scores_differing, r.differing}; });
}

}  // namespace krp
