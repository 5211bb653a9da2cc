// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/bench_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "mrpt_krp_plugin/bench/kidnap_report.h"
#include "mrpt_krp_plugin/bench/line_plot.h"
#include "mrpt_krp_plugin/bench/path_ambiguity_report.h"
#include "mrpt_krp_plugin/bench/record_groups.h"
#include "mrpt_krp_plugin/bench/seed_stage_times.h"
#include "mrpt_krp_plugin/bench/reliability.h"
#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/bench/scaling_report.h"
#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/statistics.h"

namespace krp {
namespace {

/// The tail reported beside a median.
constexpr double kTailQuantile = 0.9;

std::string ratio(double v, double ref) {
  if (!std::isfinite(v) || !std::isfinite(ref) || ref <= 0) return "-";
  return formatNumber(v / ref, 3) + "x";
}


/// Per method with a relocalizer: its best hypothesis's confidence against how often it was right.
std::string reliabilitySections(const std::vector<TrialRecord>& records, double right_within_m,
                                const HypothesisRankingParams& ranking) {
  const auto groups = groupByWorldLidarMethod(records, [](const TrialRecord& r) { return r.seed_best_confidence >= 0; });
  if (groups.empty()) return "";
  std::ostringstream o;
  o << "Does the relocalizer's confidence mean what it says? Its best hypothesis's confidence, binned, against how "
       "often that hypothesis was within "
    << right_within_m << " m of the truth (calibrated: right about as often as the mean confidence says). It says "
       "\"localized\" from " << formatNumber(ranking.min_confidence);
  if (ranking.min_localized_fit_fraction > 0)
    o << " when its best pose also explains at least " << formatNumber(ranking.min_localized_fit_fraction)
      << " of the scan's returns";
  o << ".\n\n";
  for (const auto& g : groups) {
    std::vector<ConfidenceOutcome> answers;
    for (const auto* r : g) answers.push_back(firstScanAnswer(*r, right_within_m));
    o << "**" << g.front()->world << ", " << g.front()->lidar << ", " << g.front()->method << "**\n\n"
      << reliabilityMarkdown(reliabilityTable(answers)) << "\n";
  }
  return o.str();
}

/// Which models the seeded methods ran, per world and lidar: a report made before its models were
/// replaced says so. Empty when no method used models.
std::string modelsSection(const std::vector<TrialRecord>& records) {
  std::set<std::string> lines;
  for (const auto& r : records)
    if (!r.models.empty()) lines.insert("- " + r.world + ", " + r.lidar + ": `" + r.models + "`\n");
  if (lines.empty()) return "";
  std::string md = "Models of the seeded methods:\n\n";
  for (const auto& l : lines) md += l;
  return md + "\n";
}

}  // namespace

bool seedBestRight(const TrialRecord& r, double right_within_m) {
  return r.seed_best_error_xy_m >= 0 && r.seed_best_error_xy_m <= right_within_m;
}

ConfidenceOutcome firstScanAnswer(const TrialRecord& r, double right_within_m) {
  return {r.seed_best_confidence, seedBestRight(r, right_within_m)};
}

std::string relocalizerTable(const std::vector<MethodSummary>& summaries, double right_within_m) {
  std::ostringstream o;
  for (const auto& s : summaries) {
    if (s.seed_localized_rate < 0) continue;
    if (o.tellp() == 0)
      o << "Relocalization from the first scan (methods that seed the filter with hypotheses): \"localized\" is "
           "the relocalizer's own verdict; \"best right\" is how "
           "often its best hypothesis was within " << right_within_m << " m of the truth, whatever the verdict; "
           "\"localized but wrong\" is the relocalizer's own confident-but-wrong rate: it said localized and its "
           "best was not right; \"best from matcher\" is how often its best hypothesis came from a correlative "
           "search (for the seeded methods: the zone search, which runs when the keypoints give no credible pose, or "
           "the cross-check of the best answer for look-alike places); \"scan to prior\" is the thread CPU time "
           "from the first scan to the drawn particles (relocalization and sampling, one core), median and 90th "
           "percentile over trials.\n\n"
        << "| world | lidar | method | localized | best right | localized but wrong | best from matcher | scan to prior ms "
           "(median) | (p90) |\n"
           "|---|---|---|---|---|---|---|---|---|\n";
    const auto ms = [](double seconds) { return seconds < 0 ? std::string("-") : formatNumber(1000.0 * seconds, 3); };
    o << "| " << s.world << " | " << s.lidar << " | " << s.method << " | " << formatNumber(100.0 * s.seed_localized_rate)
      << " % | " << formatNumber(100.0 * s.seed_best_right_rate) << " % | " << formatNumber(100.0 * s.seed_localized_wrong_rate)
      << " % | " << formatNumber(100.0 * s.seed_best_from_matcher_rate) << " % | " << ms(s.median_seed_cpu_s) << " | "
      << ms(s.p90_seed_cpu_s) << " |\n";
  }
  if (o.tellp() > 0) o << "\n";
  return o.str();
}

std::vector<MethodSummary> summarize(const std::vector<TrialRecord>& records, double right_within_m) {
  std::vector<MethodSummary> out;
  for (const auto& g : groupByWorldLidarMethod(records)) {
    MethodSummary s{g.front()->world, g.front()->lidar, g.front()->method};
    s.trials = static_cast<int>(g.size());
    std::vector<double> upd, dist, cpu, init, meanp, pupd, ferr, ferr_c, fphi_c, seed_cpu;
    int ok = 0, cbw = 0, car = 0, seeded = 0, seed_localized = 0, seed_right = 0, seed_localized_wrong = 0, from_matcher = 0;
    for (const auto* r : g) {
      const auto& o = r->outcome;
      if (r->seed_hypotheses >= 0) {
        ++seeded;
        seed_localized += r->seed_localized ? 1 : 0;
        const bool right = seedBestRight(*r, right_within_m);
        seed_right += right ? 1 : 0;
        seed_localized_wrong += (r->seed_localized && !right) ? 1 : 0;
        from_matcher += r->seed_best_from_matcher ? 1 : 0;
        if (r->seed_cpu_s >= 0) seed_cpu.push_back(r->seed_cpu_s);
      }
      init.push_back(static_cast<double>(o.initial_particles));
      meanp.push_back(o.mean_particles);
      ferr.push_back(o.final_error_xy_m);
      cbw += o.confident_but_wrong ? 1 : 0;
      car += o.confident_and_right ? 1 : 0;
      if (!o.converged) continue;
      ++ok;
      upd.push_back(o.updates_to_convergence);
      dist.push_back(o.distance_to_convergence_m);
      cpu.push_back(o.cpu_to_convergence_s);
      pupd.push_back(o.particle_updates_to_convergence);
      ferr_c.push_back(o.final_error_xy_m);
      fphi_c.push_back(o.final_error_phi_deg);
    }
    const auto share_of_trials = [&](int count) { return s.trials ? static_cast<double>(count) / s.trials : 0.0; };
    s.success_rate = share_of_trials(ok);
    s.confident_wrong_rate = share_of_trials(cbw);
    s.confident_right_rate = share_of_trials(car);
    if (seeded > 0) {
      s.seed_localized_rate = static_cast<double>(seed_localized) / seeded;
      s.seed_best_right_rate = static_cast<double>(seed_right) / seeded;
      s.seed_localized_wrong_rate = static_cast<double>(seed_localized_wrong) / seeded;
      s.seed_best_from_matcher_rate = static_cast<double>(from_matcher) / seeded;
    }
    if (!seed_cpu.empty()) {
      s.median_seed_cpu_s = median(seed_cpu);
      s.p90_seed_cpu_s = quantile(seed_cpu, kTailQuantile);
    }
    s.median_updates = median(upd);
    s.median_distance_m = median(dist);
    s.median_cpu_s = median(cpu);
    s.median_initial_particles = median(init);
    s.median_mean_particles = median(meanp);
    s.median_particle_updates = median(pupd);
    s.median_final_error_m = median(ferr);
    s.median_final_error_converged_m = median(ferr_c);
    s.median_final_error_phi_deg = median(fphi_c);
    out.push_back(s);
  }
  return out;
}

std::string summaryTable(const std::vector<MethodSummary>& summaries, const std::string& reference_method) {
  std::ostringstream o;
  o << "| world | lidar | method | trials | success | confident-wrong | confident-right | median updates | median distance m | "
       "median CPU s | CPU vs " << reference_method << " | initial particles | vs " << reference_method
    << " | mean particles | particle-updates | final err m (conv.) | final err deg (conv.) | final err m (all) |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& s : summaries) {
    const MethodSummary* ref = nullptr;
    for (const auto& r : summaries)
      if (r.world == s.world && r.lidar == s.lidar && r.method == reference_method) ref = &r;
    o << "| " << s.world << " | " << s.lidar << " | " << s.method << " | " << s.trials << " | "
      << formatNumber(100.0 * s.success_rate, 3) << " % | " << formatNumber(100.0 * s.confident_wrong_rate, 3) << " % | "
      << formatNumber(100.0 * s.confident_right_rate, 3) << " % | " << formatNumber(s.median_updates) << " | " << formatNumber(s.median_distance_m) << " | " << formatNumber(s.median_cpu_s) << " | "
      << (ref ? ratio(s.median_cpu_s, ref->median_cpu_s) : "-") << " | " << formatNumber(s.median_initial_particles, 6) << " | "
      << (ref ? ratio(s.median_initial_particles, ref->median_initial_particles) : "-") << " | "
      << formatNumber(s.median_mean_particles, 6) << " | " << formatNumber(s.median_particle_updates, 6) << " | "
      << formatNumber(s.median_final_error_converged_m) << " | " << formatNumber(s.median_final_error_phi_deg) << " | "
      << formatNumber(s.median_final_error_m) << " |\n";
  }
  return o.str();
}

void writeBenchReport(const std::vector<TrialRecord>& records, const BenchConfig& cfg, const std::string& command_line,
                      const std::string& out_dir) {
  namespace fs = std::filesystem;
  fs::create_directories(out_dir);
  const auto summaries = summarize(records, cfg.criteria.max_error_xy_m);

  std::ostringstream trials_csv, updates_csv;
  trials_csv << "world,lidar,method,trial,trial_seed,filter_seed,converged,updates_to_convergence,"
                "distance_to_convergence_m,cpu_to_convergence_s,initial_particles,mean_particles,"
                "particle_updates_to_convergence,final_error_xy_m,final_error_phi_deg,confident_but_wrong,confident_and_right,total_cpu_s,"
                "look_alike_searches,look_alike_search_cpu_s,look_alike_searches_unfinished,seed_hypotheses,seed_localized,seed_best_error_xy_m,seed_best_confidence,seed_best_from_matcher,seed_best_fit_fraction,seed_cpu_s,kidnap_step,kidnap_tracking_before,"
                "kidnap_updates_to_detect,kidnap_recovered,kidnap_updates_to_recover,kidnap_cpu_to_recover_s,"
                "path_verdict,path_places,path_end_places,path_closest_log_ratio,path_closest_distance_m,path_closest_source"
             << seedStageCsvHeader() << "\n";
  updates_csv << "world,lidar,method,trial,update,error_xy_m,error_phi_deg,std_xy_m,std_phi_deg,ambiguous,particles,cpu_s,"
                 "distance_m,fit_fraction,scan_unexplained,look_alike_searches,look_alike_search_cpu_s,look_alike_searches_unfinished,look_alike_unverified\n";
  for (const auto& r : records) {
    const auto& o = r.outcome;
    trials_csv << r.world << "," << r.lidar << "," << r.method << "," << r.trial << "," << r.trial_seed << ","
               << r.filter_seed << "," << o.converged << "," << o.updates_to_convergence << ","
               << o.distance_to_convergence_m << "," << o.cpu_to_convergence_s << "," << o.initial_particles << ","
               << o.mean_particles << "," << o.particle_updates_to_convergence << "," << o.final_error_xy_m << ","
               << o.final_error_phi_deg << "," << o.confident_but_wrong << "," << o.confident_and_right << "," << o.total_cpu_s << ","
               << o.look_alike_searches << "," << o.look_alike_search_cpu_s << "," << o.look_alike_searches_unfinished << "," << r.seed_hypotheses
               << "," << r.seed_localized << "," << r.seed_best_error_xy_m << "," << r.seed_best_confidence << ","
               << r.seed_best_from_matcher << "," << r.seed_best_fit_fraction << "," << r.seed_cpu_s << "," << r.kidnap_step << ","
               << r.kidnap.tracking_before << "," << r.kidnap.updates_to_detect << "," << r.kidnap.recovered << ","
               << r.kidnap.updates_to_recover << "," << r.kidnap.cpu_to_recover_s << "," << toString(r.path.verdict) << ","
               << r.path.places << "," << r.path.end_places << "," << r.path.closest_log_ratio << ","
               << r.path.closest_distance_m << "," << r.path.closest_source << seedStageCsvFields(r) << "\n";
    for (size_t i = 0; i < r.updates.size(); ++i) {
      const auto& u = r.updates[i];
      updates_csv << r.world << "," << r.lidar << "," << r.method << "," << r.trial << "," << i << "," << u.error_xy_m
                  << "," << u.error_phi_deg << "," << u.spread.xy_std_m << "," << u.spread.phi_std_deg << "," << u.ambiguous << "," << u.particles << ","
                  << u.cpu_s << "," << u.distance_m << "," << u.fit_fraction << "," << u.scan_unexplained << "," << u.look_alike_searches << ","
                  << u.look_alike_search_cpu_s << "," << u.look_alike_searches_unfinished << "," << u.look_alike_unverified << "\n";
    }
  }
  writeFileAtomically((fs::path(out_dir) / "trials.csv").string(), trials_csv.str());
  writeFileAtomically((fs::path(out_dir) / "updates.csv").string(), updates_csv.str());

  nlohmann::json j;
  j["command"] = command_line;
  j["seed"] = cfg.seed;
  j["trials_per_pair"] = cfg.trials;
  j["criteria"] = {{"max_error_xy_m", cfg.criteria.max_error_xy_m},
                   {"max_error_phi_deg", cfg.criteria.max_error_phi_deg},
                   {"confident_std_xy_m", cfg.criteria.confident.xy_std_m},
                   {"confident_std_phi_deg", cfg.criteria.confident.phi_std_deg}};
  for (const auto& s : summaries)
    j["summary"].push_back({{"world", s.world}, {"lidar", s.lidar}, {"method", s.method}, {"trials", s.trials},
                            {"success_rate", s.success_rate}, {"confident_wrong_rate", s.confident_wrong_rate},
                            {"confident_right_rate", s.confident_right_rate},
                            {"median_updates_to_convergence", s.median_updates},
                            {"median_distance_to_convergence_m", s.median_distance_m},
                            {"median_cpu_to_convergence_s", s.median_cpu_s},
                            {"median_initial_particles", s.median_initial_particles},
                            {"median_mean_particles", s.median_mean_particles},
                            {"median_particle_updates_to_convergence", s.median_particle_updates},
                            {"median_final_error_m_converged", s.median_final_error_converged_m},
                            {"median_final_error_deg_converged", s.median_final_error_phi_deg},
                            {"median_final_error_m_all", s.median_final_error_m},
                            {"seed_localized_rate", s.seed_localized_rate},
                            {"seed_best_right_rate", s.seed_best_right_rate},
                            {"seed_localized_wrong_rate", s.seed_localized_wrong_rate},
                            {"seed_best_from_matcher_rate", s.seed_best_from_matcher_rate},
                            {"median_scan_to_prior_cpu_s", s.median_seed_cpu_s},
                            {"p90_scan_to_prior_cpu_s", s.p90_seed_cpu_s}});
  // NaN medians (no converged trial) become null in JSON.
  writeFileAtomically((fs::path(out_dir) / "summary.json").string(), j.dump(2) + "\n");

  // Plots per world and lidar: fraction converged by update, median particles by update.
  std::map<std::pair<std::string, std::string>, std::map<std::string, std::vector<const TrialRecord*>>> by_pair;
  for (const auto& r : records) by_pair[{r.world, r.lidar}][r.method].push_back(&r);
  std::vector<std::string> plot_files;
  for (const auto& [pair, methods] : by_pair) {
    std::vector<PlotSeries> conv, parts;
    for (const auto& [method, recs] : methods) {
      size_t n_updates = 0;
      for (const auto* r : recs) n_updates = std::max(n_updates, r->updates.size());
      PlotSeries c{method, {}, {}}, p{method, {}, {}};
      for (size_t i = 0; i < n_updates; ++i) {
        int done = 0;
        std::vector<double> counts;
        for (const auto* r : recs) {
          if (r->outcome.converged && static_cast<size_t>(r->outcome.updates_to_convergence) <= i + 1) ++done;
          if (i < r->updates.size()) counts.push_back(static_cast<double>(r->updates[i].particles));
        }
        c.x.push_back(static_cast<double>(i + 1));
        c.y.push_back(static_cast<double>(done) / static_cast<double>(recs.size()));
        p.x.push_back(static_cast<double>(i + 1));
        p.y.push_back(median(counts));
      }
      conv.push_back(c);
      parts.push_back(p);
    }
    const std::string stem = pair.first + "_" + pair.second;
    writeLinePlot((fs::path(out_dir) / (stem + "_converged.png")).string(),
                  "Converged (and stays) by update: " + pair.first + ", " + pair.second, "update", "fraction of trials", conv);
    LinePlotParams lp;
    lp.log_y = true;
    writeLinePlot((fs::path(out_dir) / (stem + "_particles.png")).string(),
                  "Particles by update (median): " + pair.first + ", " + pair.second, "update", "particles", parts, lp);
    plot_files.push_back(stem);
  }

  std::ostringstream md;
  md << "# krp-bench report\n\nCommand:\n\n```\n" << command_line << "\n```\n\n"
     << "Base seed " << cfg.seed << ", " << cfg.trials << " trials per world and lidar; every method replays the same "
     << "simulated trials with the same filter seed. A trial converges when the filter mean is within "
     << cfg.criteria.max_error_xy_m << " m and " << cfg.criteria.max_error_phi_deg
     << " deg of the truth at some update and every later one; \"updates\" counts filter updates up to that one "
        "(1 = from the first scan). CPU is the thread CPU time of the localization code only (simulation excluded). "
        "Confident: at the last update the largest xy std of the filter's reported covariance is below "
     << cfg.criteria.confident.xy_std_m << " m and its heading std below " << cfg.criteria.confident.phi_std_deg
     << " deg; for the methods with the look-alike guard that covariance is widened to cover a place that fits "
        "the scan nearly as well (the filter reports itself ambiguous), and widened when fewer than "
     << formatNumber(100.0 * cfg.method_settings.guard.min_fit_fraction)
     << " % of the scan's returns land on mapped walls at the mean (too much unmapped clutter to vouch for "
        "the pose)"
     << (cfg.method_settings.guard.unverified_is_unsettled
             ? ", and widened while every look-alike search since the filter converged has run out of its "
               "node budget with nothing found (nothing rules out a look-alike; column look_alike_unverified of updates.csv)"
             : "")
     << ", so such an answer is not confident. "
        "Confident-wrong: confident, yet the mean is outside tolerance; confident-right: confident and within it "
        "(the share of trials where the method both is right and says so). Medians of updates, distance, CPU and particle-updates are over "
        "converged trials. Ratios are against uniform-mcl in this same run.\n\n"
     << modelsSection(records) << summaryTable(summaries) << "\n" << relocalizerTable(summaries, cfg.criteria.max_error_xy_m)
     << seedStageTable(summarizeSeedStages(records))
     // krp-bench sets both relocalizers' rankings alike; the learned one's stands for both.
     << reliabilitySections(records, cfg.criteria.max_error_xy_m, cfg.method_settings.relocalizer.verifier.ranking)
     << kidnapSection(summarizeKidnaps(records), cfg.kidnap_at_step)
     << pathAmbiguitySection(splitByPathAmbiguity(records), cfg.path_ambiguity_params);
  const auto scaling = scalingPoints(records);
  const std::string scaling_md = scalingSection(scaling, "scaling.png");
  if (!scaling_md.empty()) {
    writeScalingPlot(scaling, (fs::path(out_dir) / "scaling.png").string());
    md << scaling_md;
  }
  for (const auto& stem : plot_files)
    md << "![converged " << stem << "](" << stem << "_converged.png)\n![particles " << stem << "](" << stem
       << "_particles.png)\n\n";
  md << "Per-trial data: `trials.csv`; per-update data: `updates.csv`; machine-readable summary: `summary.json`.\n";
  writeFileAtomically((fs::path(out_dir) / "REPORT.md").string(), md.str());
}

}  // namespace krp
