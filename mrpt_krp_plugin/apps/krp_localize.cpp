// SPDX-License-Identifier: BSD-3-Clause
// krp-localize: runs the particle filter over a rawlog, pf-localization style (INI + flags).
#include <mrpt/config/CConfigFile.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>

#include "cli_args.h"
#include "mrpt_krp_plugin/bench/method_registry.h"
#include "mrpt_krp_plugin/bench/reliability.h"
#include "mrpt_krp_plugin/bench/report_format.h"
#include "mrpt_krp_plugin/bench/single_scan_sweep.h"
#include "mrpt_krp_plugin/bench/trial_metrics.h"
#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/statistics.h"
#include "mrpt_krp_plugin/logs/carmen_log.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/relocalize/confidence_calibration.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_source.h"
#include "mrpt_krp_plugin/relocalize/relocalization_output.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"
#ifdef KRP_WITH_ROS1
#include "bag_reader.h"
#endif

namespace fs = std::filesystem;
using krp::apps::CliArgs;

namespace {
constexpr char kSection[] = "localize";
using krp::apps::kMaxParticles;
using krp::apps::kMaxZones;
constexpr long long kMaxStep = std::numeric_limits<int>::max();

// The flag that gives an INI key on the command line: the same name with '-' for '_'.
std::string flagName(std::string key) {
  for (auto& c : key) if (c == '_') c = '-';
  return key;
}

// The [localize] keys: every flag but --ini, with '_' for '-', so a new flag is an INI key too.
std::set<std::string> iniKeys(const CliArgs& args) {
  std::set<std::string> keys;
  for (auto name : args.optionNames()) {
    if (name == "ini") continue;
    for (auto& c : name) if (c == '-') c = '_';
    keys.insert(name);
  }
  return keys;
}

// Settings from the INI, overridden by flags given on the command line.
std::map<std::string, std::string> mergeSettings(const CliArgs& args) {
  const auto ini_keys = iniKeys(args);
  std::map<std::string, std::string> s;
  for (const auto& k : ini_keys) s[k] = args.get(flagName(k));
  if (!args.has("ini")) return s;
  const std::string ini = args.get("ini");
  if (!fs::exists(ini)) throw krp::InputError(ini, "INI file does not exist");
  mrpt::config::CConfigFile cfg(ini);
  std::vector<std::string> sections;
  cfg.getAllSections(sections);
  for (const auto& sec : sections)
    if (sec != kSection) throw krp::InputError(ini, "unknown section [" + sec + "] (expected [localize])");
  std::vector<std::string> keys;
  cfg.getAllKeys(kSection, keys);
  for (const auto& k : keys) {
    if (!ini_keys.count(k)) throw krp::InputError(ini, "unknown key '" + k + "' in [localize]");
    if (!args.has(flagName(k))) s[k] = cfg.read_string(kSection, k, "");
  }
  // Relative paths in the INI are relative to the INI's folder.
  for (const char* k : {"map", "rawlog", "bag", "carmen", "ground_truth", "out_dir", "models", "zones", "calibration"})
    if (!args.has(flagName(k)) && !s[k].empty() && fs::path(s[k]).is_relative() && keys.end() != std::find(keys.begin(), keys.end(), k))
      s[k] = (fs::path(ini).parent_path() / s[k]).string();
  return s;
}

double toNumber(const std::map<std::string, std::string>& s, const std::string& key) {
  try {
    size_t used = 0;
    const double v = std::stod(s.at(key), &used);
    if (used == s.at(key).size()) return v;
  } catch (const std::exception&) {
  }
  throw krp::InputError(key, "'" + s.at(key) + "' is not a number");
}

/// A setting that must be a whole number in [lo, hi]: a count or an index, never cast from a
/// fraction or a negative (a negative particle count would wrap to billions).
long long toWholeNumber(const std::map<std::string, std::string>& s, const std::string& key, long long lo, long long hi) {
  return krp::apps::wholeNumberInRange(flagName(key), s.at(key), toNumber(s, key), lo, hi);
}

// What --single-scan relocalizes with: the learned models, or the global matcher when the
// method is `global-matcher`.
struct SingleScanBackend {
  std::shared_ptr<const krp::Relocalizer> learned;
  std::shared_ptr<const krp::MatcherRelocalizer> matcher;

  krp::RelocalizationResult relocalize(const mrpt::obs::CObservation2DRangeScan& scan) const {
    if (learned) return learned->relocalize(scan);
    krp::RelocalizationResult r;
    const auto start = std::chrono::steady_clock::now();
    r.ranking = matcher->relocalize(scan);
    r.times.total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return r;
  }
  std::vector<std::string> zones() const { return learned ? learned->manifest().zones : std::vector<std::string>{}; }
  krp::HypothesisSource source() const {
    return [this](const mrpt::obs::CObservation2DRangeScan& scan) { return relocalize(scan).ranking; };
  }
};

// --single-scan STEP: the relocalizer's answer for one scan, as text, JSON and a picture.
int relocalizeOneScan(const SingleScanBackend& backend, const mrpt::maps::COccupancyGridMap2D& map,
                      const std::vector<krp::RawlogStep>& steps, const std::vector<mrpt::math::TPose2D>& truth,
                      long index, const std::string& out_dir) {
  if (index >= static_cast<long>(steps.size()))
    throw krp::InputError("--single-scan", std::to_string(index) + " is past the log's " + std::to_string(steps.size()) + " steps");
  const auto scan = steps[index].observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
  if (!scan) throw krp::InputError("step " + std::to_string(index), "holds no 2D range scan");
  const auto result = backend.relocalize(*scan);
  auto j = krp::relocalizationJson(result, backend.zones());
  std::optional<mrpt::math::TPose2D> t;
  if (!truth.empty()) {
    t = truth[index];
    j["truth"] = {{"x_m", t->x}, {"y_m", t->y}, {"yaw_deg", t->phi * 180.0 / M_PI}};
  }
  const fs::path out(out_dir);
  krp::writeFileAtomically((out / "hypotheses.json").string(), j.dump(2) + "\n");
  krp::writeHypothesesPng(map, result, t, (out / "hypotheses.png").string());
  std::cout << krp::relocalizationText(result, backend.zones());
  if (t) std::cout << "truth: x " << t->x << " m, y " << t->y << " m, yaw " << t->phi * 180.0 / M_PI << " deg\n";
  std::cout << "written: " << (out / "hypotheses.json").string() << ", " << (out / "hypotheses.png").string() << "\n";
  return 0;
}

// --single-scan all: every stride-th scan relocalized on its own, counted against the truth.
int relocalizeEveryScan(const SingleScanBackend& backend, const mrpt::maps::COccupancyGridMap2D& map,
                        const std::vector<krp::RawlogStep>& steps, const std::vector<mrpt::math::TPose2D>& truth,
                        std::size_t stride, const std::string& header, const std::string& out_dir) {
  const krp::ConvergenceCriteria right;
  const auto records = krp::sweepSingleScans(backend.source(), steps, truth, stride, right, &std::cout);
  const fs::path out(out_dir);
  krp::writeFileAtomically((out / "single_scan.csv").string(), krp::sweepCsv(records));
  krp::writeSweepPng(map, records, truth, (out / "single_scan.png").string());
  std::ostringstream sum;
  sum << header << "mode: single scan, every " << stride << " scan(s), no filter\n"
      << "right means: best hypothesis within " << right.max_error_xy_m << " m and " << right.max_error_phi_deg
      << " deg of the truth\n"
      << krp::sweepSummaryText(krp::summarizeSweep(records));
  if (!truth.empty()) {
    std::vector<krp::ConfidenceOutcome> answers;
    for (const auto& r : records)
      if (r.best) answers.push_back({r.confidence, r.best_right});
    sum << "confidence against outcome (best hypothesis):\n" << krp::reliabilityMarkdown(krp::reliabilityTable(answers));
  }
  krp::writeFileAtomically((out / "krp_localize_SUMMARY.txt").string(), sum.str());
  std::cout << sum.str() << "written: " << (out / "single_scan.csv").string() << ", " << (out / "single_scan.png").string()
            << ", " << (out / "krp_localize_SUMMARY.txt").string() << "\n";
  return 0;
}
}  // namespace

// The steps from --rawlog, --carmen, or --bag through the ROS 1 wrapper when it is part of the
// build. A CARMEN log's own poses go to `logged_truth` (the map's source frame).
static std::vector<krp::RawlogStep> readSteps(std::map<std::string, std::string>& s,
                                              std::vector<mrpt::math::TPose2D>* logged_truth) {
  if (!s["carmen"].empty()) {
    krp::CarmenLogParams p;
    p.flaser_fov_deg = toNumber(s, "carmen_fov_deg");
    auto log = krp::readCarmenLog(s["carmen"], p);
    std::cout << "carmen: " << log.steps.size() << " of " << log.laser_lines << " laser lines used ("
              << log.other_records << " other records ignored";
    if (log.skipped_scans) std::cout << "; " << log.skipped_scans << " scans skipped, first: " << log.first_skip_reason;
    if (log.poses_from_odom_lines)
      std::cout << "); RAWLASER1 scans (no return at their own maximum range) with the ODOM lines' odometry";
    else
      std::cout << "); no return at >= " << log.max_range_m << " m";
    std::cout << ", laser " << log.laser_offset_x_m << " m ahead\n";
    if (log.poses_from_odom_lines && toNumber(s, "truth_from_log") != 0)
      throw krp::InputError("--truth-from-log", s["carmen"] + " has no FLASER or ROBOTLASER1 line: its poses are the "
                                                "ODOM lines' odometry, not a corrected reference");
    *logged_truth = std::move(log.logged_poses);
    return std::move(log.steps);
  }
  if (s["bag"].empty()) return krp::readRawlog(s["rawlog"]);
#ifdef KRP_WITH_ROS1
  krp::ros1::BagReadParams p;
  p.scan_topic = s["scan_topic"];
  p.odom_frame = s["odom_frame"];
  p.base_frame = s["base_frame"];
  auto bag = krp::ros1::readBag(s["bag"], p);
  std::cout << "bag: " << bag.steps.size() << " of " << bag.scans_seen << " scans used";
  if (bag.steps.size() < static_cast<size_t>(bag.scans_seen))
    std::cout << " (" << bag.skipped_no_transform << " without a transform, " << bag.skipped_bad_scan
              << " unusable; first: " << bag.first_problem << ")";
  std::cout << "\n";
  return std::move(bag.steps);
#else
  throw krp::InputError("--bag", "this build has no ROS 1 support (install ROS 1 with scripts/install_deps.sh and rebuild)");
#endif
}

static int run(int argc, char** argv) {
  CliArgs args("krp-localize",
               "Runs MRPT's particle filter over a rawlog, CARMEN log or bag from a global (unknown) start and writes "
               "the poses as CSV and a _SUMMARY.txt; with ground truth it reports the errors. Or relocalizes single "
               "scans without the filter (--single-scan). Settings come from --ini "
               "([localize] section, keys as the flags with '_') and flags override them.",
               {{"ini", "FILE", "INI file with a [localize] section", ""},
                {"map", "FILE", "map (.yaml, .gridmap[.gz], .bt/.ot)", ""},
                {"rawlog", "FILE", "MRPT rawlog with odometry + 2D scans", ""},
                {"bag", "FILE", "ROS 1 bag with LaserScan + tf instead of --rawlog (builds with ROS 1)", ""},
                {"carmen", "FILE", "CARMEN log (.log or .log.gz; FLASER / ROBOTLASER1 lines) instead of --rawlog", ""},
                {"carmen-fov-deg", "DEG", "--carmen: field of view of FLASER lines (they state none)", "180"},
                {"truth-from-log", "0|1", "--carmen: the log's own poses are the ground truth (a SLAM-corrected log)", "0"},
                {"scan-topic", "TOPIC", "--bag: the LaserScan topic", "/scan"},
                {"odom-frame", "FRAME", "--bag: odometry frame", "odom"},
                {"base-frame", "FRAME", "--bag: robot frame", "base_link"},
                {"method", "NAME", "uniform-mcl, amcl-kld, amcl-kld-50k, seeded, seeded-no-uniform, seeded-no-cross-check, seeded-no-guard, "
                 "seeded-keypoints-only, seeded-spread-count, seeded-later-scans, global-matcher or global-matcher-guarded", "amcl-kld"},
                {"models", "DIR", "seeded / single scan: krp-train-map's model folder (manifest.json)", ""},
                {"zones", "FILE", "seeded / single scan: the zones.yaml the models were trained on (default: the one "
                 "beside the models when their manifest names it); when the keypoints give no credible pose, the "
                 "classifier's most likely zone is searched by the correlative matcher", ""},
                {"calibration", "FILE", "seeded / global-matcher: the map's confidence calibration (krp-bench "
                 "--fit-calibration), applied before the 'localized' threshold", ""},
                {"min-localized-fit", "F", "seeded / global-matcher: a scan's best hypothesis must explain at least "
                 "this share of its returns to be called localized (0 = off)",
                 krp::formatNumber(krp::HypothesisRankingParams{}.min_localized_fit_fraction)},
                {"single-scan", "STEP|all", "relocalize from this step's scan only: print the hypotheses, write "
                 "hypotheses.json and hypotheses.png; 'all': every scan on its own, written as single_scan.csv/.png "
                 "with counts against the ground truth (-1 = run the filter). Uses --models, or the global matcher "
                 "with --method global-matcher", "-1"},
                {"single-scan-stride", "N", "--single-scan all: every N-th scan", "1"},
                {"top-zones", "N", "seeded: zones whose keypoints are aligned",
                 std::to_string(krp::RelocalizerParams{}.top_zones)},
                {"top-turns", "N", "seeded, wall-aligned models: submap turns the keypoint model runs on (1 to 4, the "
                 "classifier's surest first)", std::to_string(krp::RelocalizerParams{}.top_turns)},
                {"keypoints-every-turn", "0|1", "seeded: 1 runs the keypoint model on every one of --top-turns; 0 "
                 "runs the next turn only while no turn gave a credible answer (with the cross-check)",
                 krp::RelocalizerParams{}.stop_turns_once_localized ? "0" : "1"},
                {"matcher-roots-across-headings", "0|1", "seeded / global-matcher: 1 lets every correlative search "
                 "visit its coarsest nodes across headings, highest bound first; 0 goes heading after heading (the "
                 "matcher before commit 61986f2: the same best scores, but a place that ties exactly with another "
                 "may be found instead of it)", krp::CorrelativeMatcherParams{}.roots_across_headings ? "1" : "0"},
                {"search-zones", "N", "seeded, with --zones: the classifier's most likely zones searched when the "
                 "keypoints give no credible pose (0 = no zone search)", "1"},
                {"guard-recheck-every", "N", "methods with the look-alike guard (seeded, global-matcher-guarded): while "
                 "the filter stays converged, its whole-map look-alike search runs again every N updates (0 = only "
                 "when the filter converges afresh); on a large map with a long-range scanner that search is most of "
                 "the filter's time", std::to_string(krp::LookAlikeGuardParams{}.recheck_every_updates)},
                {"guard-max-search-nodes", "N", "methods with the look-alike guard: nodes one look-alike search may "
                 "score (0 = no limit); a converged filter whose searches all ran out of it with nothing found is "
                 "reported unverified, its std widened (raise it for a large map)",
                 std::to_string(krp::LookAlikeGuardParams{}.max_search_nodes)},
                {"guard-nodes-per-update", "N", "methods with the look-alike guard: nodes of look-alike search one "
                 "update may score; a search that needs more pauses and goes on at the next updates, the pose "
                 "reported unverified meanwhile, so no update stalls on a large map (0 = each search runs to its end)",
                 std::to_string(krp::LookAlikeGuardParams{}.max_nodes_per_update)},
                {"seeded-uniform-fraction", "F", "seeded: share of particles spread uniformly", "0.05"},
                {"seeded-uniform-start-shrinks", "0|1", "seeded methods: 1 lets a filter that started uniform (no "
                 "hypothesis) shrink by KLD sampling once converged, down to the seeded floor; 0 keeps its count",
                 krp::SeededInitParams{}.fallback_shrinks ? "1" : "0"},
                {"ground-truth", "FILE", "ground truth 'step x y phi' (optional)", ""},
                {"out-dir", "DIR", "output folder", "out/localize"},
                {"seed", "N", "filter seed", "1"},
                {"uniform-particles", "N", "uniform-mcl: fixed particle count (0 = by density)", "0"},
                {"uniform-particles-per-m2", "D", "uniform-mcl: particles per m^2", "40"},
                {"kld-max", "N", "amcl-kld: max particles", "5000"},
                {"kld-min", "N", "amcl-kld: min particles", "100"}});
  if (!args.parse(argc, argv)) return 0;
  auto s = mergeSettings(args);
  const int inputs = !s["rawlog"].empty() + !s["bag"].empty() + !s["carmen"].empty();
  if (s["map"].empty() || inputs != 1)
    throw krp::InputError("arguments", "--map and one of --rawlog, --carmen or --bag are required (flags or INI)\n" + args.usage());
  const bool truth_from_log = toNumber(s, "truth_from_log") != 0;
  if (truth_from_log && (s["carmen"].empty() || !s["ground_truth"].empty()))
    throw krp::InputError("--truth-from-log", "needs --carmen and no --ground-truth");

  const auto filter_seed = static_cast<uint32_t>(toWholeNumber(s, "seed", 0, std::numeric_limits<uint32_t>::max()));
  krp::MethodSettings ms;
  ms.uniform.particles = static_cast<size_t>(toWholeNumber(s, "uniform_particles", 0, kMaxParticles));
  ms.uniform.particles_per_m2 = toNumber(s, "uniform_particles_per_m2");
  ms.amcl.max_particles = static_cast<size_t>(toWholeNumber(s, "kld_max", 1, kMaxParticles));
  ms.amcl.min_particles = static_cast<size_t>(toWholeNumber(s, "kld_min", 1, kMaxParticles));
  ms.relocalizer.top_zones = static_cast<int>(toWholeNumber(s, "top_zones", 0, kMaxZones));
  ms.relocalizer.top_turns = static_cast<int>(toWholeNumber(s, "top_turns", 1, 4));
  const auto every_turn = toNumber(s, "keypoints_every_turn");
  if (every_turn != 0 && every_turn != 1) throw krp::InputError("--keypoints-every-turn", "must be 0 or 1");
  ms.relocalizer.stop_turns_once_localized = every_turn == 0;
  ms.relocalizer.zone_search.zones = static_cast<int>(toWholeNumber(s, "search_zones", 0, kMaxZones));
  const auto roots_across = toNumber(s, "matcher_roots_across_headings");
  if (roots_across != 0 && roots_across != 1) throw krp::InputError("--matcher-roots-across-headings", "must be 0 or 1");
  krp::useMatcherRootsAcrossHeadings(roots_across == 1, ms.relocalizer, ms.matcher);
  krp::useMinLocalizedFitFraction(toNumber(s, "min_localized_fit"), ms.relocalizer, ms.matcher);
  if (!s["calibration"].empty())
    krp::useConfidenceCalibration(krp::readConfidenceCalibration(s["calibration"]), ms.relocalizer, ms.matcher);
  ms.seeded.uniform_fraction = toNumber(s, "seeded_uniform_fraction");
  const auto shrinks = toNumber(s, "seeded_uniform_start_shrinks");
  if (shrinks != 0 && shrinks != 1) throw krp::InputError("--seeded-uniform-start-shrinks", "must be 0 or 1");
  if (shrinks == 0) ms.seeded.fallback_shrinks.reset();
  ms.guard.recheck_every_updates = static_cast<int>(toWholeNumber(s, "guard_recheck_every", 0, krp::LookAlikeGuardParams::kMaxRecheckEveryUpdates));
  ms.guard.max_search_nodes = toWholeNumber(s, "guard_max_search_nodes", 0, krp::LookAlikeGuardParams::kMaxSearchNodesLimit);
  ms.guard.max_nodes_per_update = toWholeNumber(s, "guard_nodes_per_update", 0, krp::LookAlikeGuardParams::kMaxSearchNodesLimit);
  const bool every_scan = s["single_scan"] == "all";
  const auto single_scan = every_scan ? 0L : static_cast<long>(toWholeNumber(s, "single_scan", -1, kMaxStep));
  const auto stride = static_cast<long>(toWholeNumber(s, "single_scan_stride", 1, kMaxStep));
  const bool single_scan_mode = every_scan || single_scan >= 0;
  const bool use_matcher = krp::methodNeedsMatcher(s["method"]);
  const auto map = krp::loadOccupancyMap(s["map"]);
  std::shared_ptr<const krp::Relocalizer> relocalizer;
  if (krp::methodNeedsModels(s["method"]) || (single_scan_mode && !use_matcher)) {
    if (s["models"].empty())
      throw krp::InputError("--models", "required by method '" + s["method"] + "' and by --single-scan unless --method global-matcher");
    // A non-seeded method (single-scan mode) gets the seeded relocalizer's parameters.
    const auto rp = krp::relocalizerParamsFor(s["method"], ms.relocalizer);
    const bool zone_search = !s["zones"].empty() && (krp::methodUsesZoneSearch(s["method"]) || !krp::methodNeedsModels(s["method"]));
    relocalizer = zone_search ? std::make_shared<krp::Relocalizer>(s["models"], *map.grid, rp, krp::readZonesYaml(s["zones"]))
                              : std::make_shared<krp::Relocalizer>(s["models"], *map.grid, rp);
    if (const auto missing = relocalizer->zoneSearchMissing(); !missing.empty())
      std::cerr << "krp-localize: warning: " << missing << " (--zones)\n";
  }
  std::vector<mrpt::math::TPose2D> truth;
  const auto steps = readSteps(s, &truth);
  if (truth_from_log)
    for (auto& t : truth) t = map.toGridFrame(t);
  else
    truth.clear();
  if (!s["ground_truth"].empty()) {
    truth = krp::readGroundTruth(s["ground_truth"]);
    if (truth.size() != steps.size())
      throw krp::InputError(s["ground_truth"], std::to_string(truth.size()) + " poses for " + std::to_string(steps.size()) +
                                                   " steps");
  }
  krp::MethodResources resources;
  if (relocalizer) resources.relocalizers[s["method"]] = relocalizer;
  if (krp::methodNeedsMatcher(s["method"]) || (single_scan_mode && use_matcher))
    resources.matcher = std::make_shared<krp::MatcherRelocalizer>(*map.grid, ms.matcher);
  const std::string input = !s["bag"].empty() ? s["bag"] : !s["carmen"].empty() ? s["carmen"] : s["rawlog"];
  if (single_scan_mode) {
    const SingleScanBackend backend{use_matcher ? nullptr : relocalizer, resources.matcher};
    if (!every_scan) return relocalizeOneScan(backend, *map.grid, steps, truth, single_scan, s["out_dir"]);
    const std::string header = "krp-localize summary\ncommand: " + args.commandLine() + "\nmap: " + s["map"] + "\ninput: " +
                               input + "\nrelocalizer: " + (use_matcher ? "global-matcher" : "learned, " + krp::modelsIdentity(relocalizer->manifest())) + "\n";
    return relocalizeEveryScan(backend, *map.grid, steps, truth, static_cast<std::size_t>(stride), header, s["out_dir"]);
  }
  auto init = krp::makeInitializer(s["method"], ms, resources);
  krp::MclParams mp;
  mp.seed = filter_seed;
  mp.see_through.enabled = krp::methodUsesSeeThrough(s["method"]);
  mp.later_scans.enabled = krp::methodSeedsFromLaterScans(s["method"]);
  krp::MclLocalizer loc(map.grid, init, mp);
  if (krp::methodUsesLookAlikeGuard(s["method"])) loc.setLookAlikeGuard(krp::makeLookAlikeGuard(*map.grid, ms));

  std::ostringstream csv;
  csv << "step,x_m,y_m,phi_rad,std_xy_m,std_phi_deg,ambiguous,scan_unexplained,particles,cpu_s,look_alike_searches,"
         "look_alike_search_cpu_s,look_alike_searches_unfinished,look_alike_unverified"
      << (truth.empty() ? "" : ",error_xy_m,error_phi_deg")
      << "\n";
  std::vector<krp::UpdateRecord> records;
  krp::MclEstimate e;
  for (size_t i = 0; i < steps.size(); ++i) {
    e = loc.update(steps[i]);
    const auto r = krp::makeUpdateRecord(e, truth.empty() ? e.mean : truth[i], 0.0);
    records.push_back(r);
    csv << i << "," << e.mean.x << "," << e.mean.y << "," << e.mean.phi << "," << r.spread.xy_std_m << "," << r.spread.phi_std_deg << ","
        << r.ambiguous << "," << r.scan_unexplained << "," << e.particles << "," << e.cpu_s << "," << e.look_alike_searches << ","
        << e.look_alike_search_cpu_s << "," << e.look_alike_searches_unfinished << "," << e.look_alike_unverified;
    if (!truth.empty()) csv << "," << r.error_xy_m << "," << r.error_phi_deg;
    csv << "\n";
  }
  const fs::path out(s["out_dir"]);
  krp::writeFileAtomically((out / "poses.csv").string(), csv.str());
  std::ostringstream sum;
  const auto& last = records.back();
  // Outside single-scan mode a relocalizer exists exactly for the methods that need models.
  sum << "krp-localize summary\ncommand: " << args.commandLine() << "\nmap: " << s["map"] << "\ninput: " << input
      << "\nmethod: " << init->name()
      << (relocalizer ? "\nmodels: " + krp::modelsIdentity(relocalizer->manifest()) : "")
      << "\nsteps: " << steps.size() << "\ninitial particles: " << records.front().particles
      << "\nfinal particles: " << last.particles << "\nfinal pose (grid frame): " << loc.particles().getMeanVal().asString()
      << "\nfinal std: " << last.spread.xy_std_m << " m, " << last.spread.phi_std_deg << " deg\n";
  if (e.ambiguous_with)
    sum << "ambiguous: a look-alike place fits the last scan nearly as well, at "
        << mrpt::poses::CPose2D(*e.ambiguous_with).asString() << " (grid frame); the std above covers both\n";
  if (e.scan_unexplained)
    sum << "unsettled: the map explains only " << e.fit_fraction
        << " of the last scan's returns (clutter?); the std above is widened\n";
  if (e.look_alike_unverified) {
    sum << "unverified: ";
    if (e.look_alike_search_pending)
      sum << "no look-alike search since the filter converged has finished; one is still running, "
          << "spread over updates (--guard-nodes-per-update " << ms.guard.max_nodes_per_update
          << "), so nothing rules out a look-alike place yet";
    else
      sum << "every look-alike search since the filter converged ran out of its node budget "
          << "(--guard-max-search-nodes " << ms.guard.max_search_nodes
          << ") with nothing found, so nothing rules out a look-alike place";
    sum << (ms.guard.unverified_is_unsettled ? "; the std above is widened" : "") << "\n";
  }
  // The totals over the updates; the convergence fields mean something only with a truth.
  const auto o = krp::evaluateTrial(records, krp::ConvergenceCriteria{});
  sum << "localization CPU: " << o.total_cpu_s << " s\n";
  if (krp::methodUsesLookAlikeGuard(s["method"]))
    sum << "look-alike searches: " << o.look_alike_searches << ", " << o.look_alike_search_cpu_s
        << " s of that CPU (every " << ms.guard.recheck_every_updates
        << " update(s) while converged; --guard-recheck-every spaces them out); " << o.look_alike_searches_unfinished
        << " ran out of their node budget with nothing found\n";
  if (!truth.empty()) {
    std::vector<double> errs;
    for (const auto& r : records) errs.push_back(r.error_xy_m);
    sum << "converged: " << (o.converged ? "yes" : "no") << "\nupdates to convergence: " << o.updates_to_convergence
        << "\nfinal error: " << o.final_error_xy_m << " m, " << o.final_error_phi_deg << " deg\nmedian error: "
        << krp::median(errs) << " m\nconfident but wrong: " << (o.confident_but_wrong ? "yes" : "no") << "\n";
  }
  krp::writeFileAtomically((out / "krp_localize_SUMMARY.txt").string(), sum.str());
  std::cout << sum.str() << "poses: " << (out / "poses.csv").string() << "\n";
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-localize", run, argc, argv); }
