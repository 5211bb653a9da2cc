// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/bench_runner.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/progress_bar.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/logs/carmen_log.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

namespace krp {
namespace {
// Streams of deriveSeed: one per (world, lidar, trial), one for the filter, and one for the
// second trial a kidnapped robot is carried into.
constexpr uint64_t kWorldStride = 1000000, kLidarStride = 10000, kFilterStream = 7777777, kKidnapStream = 5555555;
// A trial of `params.steps` steps whose robot is carried, at step `cfg.kidnap_at_step`, to the
// start of a second trial at least `cfg.kidnap_min_distance_m` away.
Trial generateKidnapTrial(const mrpt::maps::COccupancyGridMap2D& map, const LidarProfile& lidar, const TrialParams& params,
                          const BenchConfig& cfg, uint64_t trial_seed) {
  if (cfg.kidnap_at_step > params.steps)
    throw InputError("kidnap step", std::to_string(cfg.kidnap_at_step) + " is past the trial's " + std::to_string(params.steps) +
                                        " steps");
  TrialParams first = params, second = params;
  first.steps = cfg.kidnap_at_step - 1;
  second.steps = params.steps - cfg.kidnap_at_step;
  const Trial before = generateTrial(map, lidar, first, trial_seed);
  for (int draw = 0; draw < cfg.kidnap_max_draws; ++draw) {
    const Trial after = generateTrial(map, lidar, second, deriveSeed(trial_seed, kKidnapStream + static_cast<uint64_t>(draw)));
    const auto& a = before.truth.back();
    const auto& b = after.truth.front();
    if (std::hypot(a.x - b.x, a.y - b.y) >= cfg.kidnap_min_distance_m) return kidnapTrial(before, after);
  }
  throw InputError("kidnap", "no second start at least " + std::to_string(cfg.kidnap_min_distance_m) + " m away in " +
                                 std::to_string(cfg.kidnap_max_draws) + " draws: the map is too small");
}

// The polygon of the world's trial_start_zone (empty when it names none).
std::vector<mrpt::math::TPoint2D> trialStartRegion(const World& world) {
  if (world.trial_start_zone.empty()) return {};
  for (const auto& zone : readZonesYaml(world.zones_path))
    if (zone.name == world.trial_start_zone) return zone.polygon;
  throw InputError("world '" + world.name + "'",
                   "trial_start_zone '" + world.trial_start_zone + "' is not a zone of " + world.zones_path);
}

}  // namespace

std::vector<TrialRecord> runBench(const BenchConfig& cfg, std::ostream& log) {
  const auto known = methodNames();
  bool need_matcher = false;
  std::vector<std::string> seeded_methods;
  for (const auto& m : cfg.methods) {  // fail early on a bad name
    if (std::find(known.begin(), known.end(), m) == known.end()) makeInitializer(m, cfg.method_settings);
    if (methodNeedsModels(m)) seeded_methods.push_back(m);
    need_matcher = need_matcher || methodNeedsMatcher(m);
  }
  struct Job {
    World world;
    std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map;
    /// The filters' map: its likelihood field computed once, at loading, as amcl does.
    SensorModelMap filter_map;
    LidarProfile lidar;
    size_t world_index, lidar_index;
    MethodResources resources;
    std::vector<mrpt::math::TPoint2D> start_region;  ///< where trials start (empty: anywhere)
    std::shared_ptr<const PathAmbiguityCheck> path_check;  ///< when BenchConfig::path_ambiguity
    std::string models;  ///< TrialRecord::models of the seeded methods
  };
  for (const int t : cfg.only_trials)
    if (t < 0 || t >= cfg.trials)
      throw InputError("trial " + std::to_string(t), "is not one of the run's trials 0.." + std::to_string(cfg.trials - 1));
  std::vector<int> trial_indices = cfg.only_trials;
  if (trial_indices.empty())
    for (int t = 0; t < cfg.trials; ++t) trial_indices.push_back(t);
  std::vector<World> worlds;
  for (const auto& f : cfg.world_files) worlds.push_back(readWorld(f));
  for (const auto& named : cfg.method_settings.models_by_world) {  // a typo would silently use the default folder
    const bool run = std::any_of(worlds.begin(), worlds.end(), [&](const World& w) { return w.name == named.first; });
    if (!run) throw InputError("models of world '" + named.first + "'", "no world of that name is run");
  }
  std::vector<Job> jobs;
  for (size_t wi = 0; wi < worlds.size(); ++wi) {
    const World& w = worlds[wi];
    const auto map = loadOccupancyMap(w.map_path).grid;
    const auto filter_map = prepareSensorModelMap(*map, cfg.mcl.sensor);
    const auto start_region = trialStartRegion(w);
    const auto lidars = cfg.lidars.empty() ? std::vector<std::string>{w.default_lidar_profile} : cfg.lidars;
    std::shared_ptr<const MatcherRelocalizer> matcher;
    if (need_matcher) matcher = std::make_shared<MatcherRelocalizer>(*map, cfg.method_settings.matcher);
    std::shared_ptr<const LookAlikeGuard> guard;
    if (std::any_of(cfg.methods.begin(), cfg.methods.end(), methodUsesLookAlikeGuard))
      guard = makeLookAlikeGuard(*map, cfg.method_settings);
    // Only the methods that seed from hypotheses (models or the matcher) draw a uniform share over
    // free cells; the others need no copy of the map's cells.
    std::shared_ptr<const FreeCells> free_cells;
    if (!seeded_methods.empty() || need_matcher)
      free_cells = std::make_shared<const FreeCells>(*filter_map.grid, cfg.method_settings.seeded.free_cell_min_freeness);
    std::shared_ptr<const PathAmbiguityCheck> path_check;
    if (cfg.path_ambiguity && cfg.kidnap_at_step == 0) {
      path_check = std::make_shared<PathAmbiguityCheck>(
          filter_map.grid, std::make_shared<CorrelativeMatcher>(*map, cfg.method_settings.matcher.matcher),
          cfg.mcl.see_through.enabled ? std::make_shared<SeeThroughPenalty>(*map, cfg.mcl.sensor, cfg.mcl.see_through) : nullptr,
          cfg.path_ambiguity_params);
    }
    for (size_t li = 0; li < lidars.size(); ++li) {
      MethodResources res;
      std::string models_identity;
      res.matcher = matcher;
      res.guard = guard;
      res.free_cells = free_cells;
      if (!seeded_methods.empty()) {
        const auto models = modelsFolder(cfg.method_settings.models_root, cfg.method_settings.models_by_world, w, lidars[li]);
        const auto zones = readZonesYaml(w.zones_path);
        for (const auto& m : seeded_methods) {
          const auto rp = relocalizerParamsFor(m, cfg.method_settings.relocalizer);
          res.relocalizers[m] = methodUsesZoneSearch(m) ? std::make_shared<Relocalizer>(models, *map, rp, zones)
                                                        : std::make_shared<Relocalizer>(models, *map, rp);
        }
        const auto& r = *res.relocalizers.begin()->second;
        models_identity = modelsIdentity(r.manifest());
        log << "krp-bench: " << w.name << " / " << lidars[li] << ": models " << models_identity << " (lidar "
            << r.manifest().lidar_name << ")\n";
      }
      jobs.push_back({w, map, filter_map, w.lidar(lidars[li]), wi, li, res, start_region, path_check, models_identity});
    }
  }
  log << "krp-bench: base seed " << cfg.seed << "; " << jobs.size() << " world/lidar pair(s) x " << cfg.methods.size()
      << " method(s) x " << trial_indices.size() << " trial(s)\n";

  std::vector<TrialRecord> out;
  ProgressBar bar("bench", jobs.size() * trial_indices.size() * cfg.methods.size(), log);
  for (const auto& job : jobs) {
    const double free_m2 = freeAreaM2(*job.map);
    for (const int t : trial_indices) {
      const uint64_t trial_seed =
          deriveSeed(cfg.seed, job.world_index * kWorldStride + job.lidar_index * kLidarStride + static_cast<uint64_t>(t));
      const uint64_t filter_seed = deriveSeed(trial_seed, kFilterStream);
      TrialParams tp = cfg.trial;
      tp.clutter = job.world.clutter;
      tp.start_region = job.start_region;
      const Trial trial = cfg.kidnap_at_step > 0 ? generateKidnapTrial(*job.map, job.lidar, tp, cfg, trial_seed)
                                                 : generateTrial(*job.map, job.lidar, tp, trial_seed);
      const auto steps = trialToSteps(trial);
      if (!cfg.rawlog_dir.empty()) {
        const std::string base =
            (std::filesystem::path(cfg.rawlog_dir) / (job.world.name + "_" + job.lidar.name + "_trial" + std::to_string(t))).string();
        writeTrialRawlog(trial, base + ".rawlog", base + "_groundtruth.txt");
        writeTrialCarmenLog(trial, base + ".carmen.log");
      }
      std::vector<TrialRecord> trial_records;
      std::vector<EndPlace> wrong_ends;  // for the path check, which runs once every method has
      for (const auto& method : cfg.methods) {
        MclParams mp = cfg.mcl;
        mp.seed = static_cast<uint32_t>(filter_seed);
        if (cfg.kidnap_at_step > 0) mp.kidnap.enabled = true;
        if (!methodUsesSeeThrough(method)) mp.see_through.enabled = false;
        mp.later_scans.enabled = methodSeedsFromLaterScans(method);
        MethodSettings ms = cfg.method_settings;
        ms.seeded.seed = filter_seed;
        const auto init = makeInitializer(method, ms, job.resources);
        MclLocalizer loc(job.filter_map, init, mp);
        if (methodUsesLookAlikeGuard(method)) loc.setLookAlikeGuard(job.resources.guard);
        TrialRecord rec;
        rec.world = job.world.name;
        rec.lidar = job.lidar.name;
        rec.method = method;
        rec.trial = t;
        rec.trial_seed = trial_seed;
        rec.filter_seed = filter_seed;
        rec.free_area_m2 = free_m2;
        if (methodNeedsModels(method)) rec.models = job.models;
        size_t last_initialization = 0;  // the seeding to check is the last one (after a kidnap, the re-seeding)
        for (size_t i = 0; i < steps.size(); ++i) {
          const auto estimate = loc.update(steps[i]);
          if (estimate.initialized) last_initialization = i;
          rec.updates.push_back(makeUpdateRecord(estimate, trial.truth[i], trial.distance_m[i]));
          const auto& last = rec.updates.back();
          if (i + 1 == steps.size() && !withinTolerance(last.error_xy_m, last.error_phi_deg, cfg.criteria))
            wrong_ends.push_back({method, estimate.mean});
        }
        if (const auto seeded = std::dynamic_pointer_cast<SeededInitializer>(init); seeded && seeded->lastSeeding()) {
          const auto& ranking = seeded->lastSeeding()->ranking;
          rec.seed_hypotheses = static_cast<int>(ranking.hypotheses.size());
          rec.seed_localized = ranking.localized;
          rec.seed_cpu_s = seeded->lastSeeding()->cpu_s;
          rec.seed_stage_times = seeded->lastSeeding()->stage_times;
          if (!ranking.hypotheses.empty()) {
            const auto& best = ranking.hypotheses.front().pose;
            rec.seed_best_confidence = ranking.hypotheses.front().confidence;
            rec.seed_best_from_matcher = ranking.hypotheses.front().origin == PoseOrigin::kMatcher;
            rec.seed_best_fit_fraction = ranking.hypotheses.front().fit_fraction;
            const auto& truth = trial.truth[last_initialization];
            rec.seed_best_error_xy_m = std::hypot(best.x - truth.x, best.y - truth.y);
          }
        }
        rec.outcome = evaluateTrial(rec.updates, cfg.criteria);
        if (cfg.kidnap_at_step > 0) {
          rec.kidnap_step = cfg.kidnap_at_step;
          rec.kidnap = evaluateKidnap(rec.updates, static_cast<std::size_t>(cfg.kidnap_at_step), cfg.criteria);
        }
        bar.advance(1, job.world.name + "/" + method + " trial " + std::to_string(t) + " seed " + std::to_string(trial_seed));
        trial_records.push_back(std::move(rec));
      }
      if (job.path_check) {
        const auto path = job.path_check->check(trial.truth, trial.scans, wrong_ends);
        for (auto& rec : trial_records) rec.path = path;
      }
      for (auto& rec : trial_records) out.push_back(std::move(rec));
    }
  }
  bar.finish();
  return out;
}

}  // namespace krp
