// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/method_registry.h"

#include <algorithm>
#include <filesystem>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/inference/model_manifest.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/relocalize/training_map_check.h"

namespace krp {

std::vector<std::string> methodNames() {
  return {"uniform-mcl",           "amcl-kld",       "amcl-kld-50k", "seeded", "seeded-no-uniform", "seeded-no-cross-check",
          "seeded-no-guard",       "seeded-keypoints-only", "seeded-spread-count", "seeded-later-scans",
          "global-matcher",        "global-matcher-guarded"};
}

namespace {
constexpr const char* kKeypointsOnly = "seeded-keypoints-only";
constexpr const char* kNoCrossCheck = "seeded-no-cross-check";
constexpr const char* kNoGuard = "seeded-no-guard";
constexpr const char* kSpreadCount = "seeded-spread-count";
constexpr const char* kMatcherGuarded = "global-matcher-guarded";
constexpr const char* kLaterScans = "seeded-later-scans";
}  // namespace

bool methodNeedsModels(const std::string& name) {
  return name == "seeded" || name == "seeded-no-uniform" || name == kNoCrossCheck || name == kNoGuard ||
         name == kKeypointsOnly || name == kSpreadCount || name == kLaterScans;
}
bool methodSeedsFromLaterScans(const std::string& name) { return name == kLaterScans; }
bool methodUsesLookAlikeGuard(const std::string& name) {
  return (methodNeedsModels(name) && name != kNoGuard && name != kKeypointsOnly) || name == kMatcherGuarded;
}
std::shared_ptr<const LookAlikeGuard> makeLookAlikeGuard(const mrpt::maps::COccupancyGridMap2D& map,
                                                         const MethodSettings& settings) {
  return std::make_shared<LookAlikeGuard>(std::make_shared<CorrelativeMatcher>(map, settings.relocalizer.matcher),
                                          settings.guard);
}
bool methodUsesSeeThrough(const std::string& name) { return methodUsesLookAlikeGuard(name); }
bool methodUsesZoneSearch(const std::string& name) { return methodNeedsModels(name) && name != kKeypointsOnly; }

RelocalizerParams relocalizerParamsFor(const std::string& name, RelocalizerParams base) {
  if (name == kKeypointsOnly || name == kNoCrossCheck) base.cross_check.enabled = false;
  if (name == kKeypointsOnly) base.zone_search.zones = 0;
  return base;
}
bool methodNeedsMatcher(const std::string& name) { return name == "global-matcher" || name == kMatcherGuarded; }

std::vector<std::string> modelsOfTheSameMap(const std::string& root, const World& world, const std::string& lidar) {
  std::vector<std::string> found;
  std::error_code error;
  if (!std::filesystem::is_directory(root, error)) return found;
  std::shared_ptr<mrpt::maps::COccupancyGridMap2D> map;
  try {
    map = loadOccupancyMap(world.map_path).grid;
  } catch (const std::exception&) {
    return found;  // the run reports an unreadable map itself
  }
  for (const auto& entry : std::filesystem::directory_iterator(root, error)) {
    try {
      const auto manifest = readModelManifest(entry.path().string());
      if (manifest.lidar_name != lidar) continue;
      requireTrainingMap(manifest, *map);  // throws for another map
      found.push_back(entry.path().string());
    } catch (const std::exception&) {
      // no manifest, a broken one, or models of another map: not a candidate
    }
  }
  std::sort(found.begin(), found.end());  // directory order is the file system's
  return found;
}

std::string modelsFolder(const std::string& root, const std::map<std::string, std::string>& by_world,
                         const World& world, const std::string& lidar) {
  if (const auto named = by_world.find(world.name); named != by_world.end()) {
    if (!std::filesystem::exists(std::filesystem::path(named->second) / "manifest.json"))
      throw InputError(named->second, "named as the models of world '" + world.name +
                                          "' but holds no manifest.json (krp-train-map's output)");
    return named->second;
  }
  const std::string name = lidar == world.default_lidar_profile ? world.name : world.name + "_" + lidar;
  const auto folder = (std::filesystem::path(root) / name).string();
  if (!std::filesystem::exists(std::filesystem::path(folder) / "manifest.json")) {
    std::string message = "no models of world '" + world.name + "' for lidar '" + lidar + "' (no manifest.json): " +
                          "train them with krp-train-map --world " + world.name + " --lidar " + lidar + " --out " + folder;
    const auto same_map = modelsOfTheSameMap(root, world, lidar);
    if (!same_map.empty())
      message += "; or, as " + same_map.front() + " was trained on this world's map for that lidar, use them: " +
                 "--models-for " + world.name + "=" + same_map.front();
    throw InputError(folder, message);
  }
  return folder;
}

std::shared_ptr<ParticleInitializer> makeInitializer(const std::string& name, const MethodSettings& s,
                                                     const MethodResources& resources) {
  if (name == "uniform-mcl") return std::make_shared<UniformInitializer>(s.uniform);
  if (name == "amcl-kld") return std::make_shared<AmclKldInitializer>(s.amcl, name);
  if (name == "amcl-kld-50k") {
    AmclKldParams p = s.amcl;
    p.max_particles = s.amcl_high_max_particles;
    return std::make_shared<AmclKldInitializer>(p, name);
  }
  SeededInitParams seeded = s.seeded;
  seeded.fallback = s.uniform;
  if (methodNeedsModels(name)) {
    const auto found = resources.relocalizers.find(name);
    const auto relocalizer = found == resources.relocalizers.end() ? nullptr : found->second;
    if (!relocalizer) throw InputError("method '" + name + "'", "needs trained models (a models folder with manifest.json)");
    if (name == "seeded-no-uniform") seeded.uniform_fraction = 0.0;
    if (name == kSpreadCount) seeded.count_from_spread = KldSampleSizeParams{};
    const SeededInitializer::TimedHypothesisSource source = [relocalizer](const mrpt::obs::CObservation2DRangeScan& scan) {
      auto result = relocalizer->relocalize(scan);
      return TimedRanking{std::move(result.ranking), result.times};
    };
    auto init = std::make_shared<SeededInitializer>(source, seeded, name);
    init->useFreeCells(resources.free_cells);
    return init;
  }
  if (methodNeedsMatcher(name)) {
    const auto matcher = resources.matcher;
    if (!matcher) throw InputError("method '" + name + "'", "needs the map's global matcher");
    auto init = std::make_shared<SeededInitializer>(
        [matcher](const mrpt::obs::CObservation2DRangeScan& scan) { return matcher->relocalize(scan); }, seeded, name);
    init->useFreeCells(resources.free_cells);
    return init;
  }
  std::string known;
  for (const auto& n : methodNames()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("method '" + name + "'", "unknown (known: " + known + ")");
}

}  // namespace krp
