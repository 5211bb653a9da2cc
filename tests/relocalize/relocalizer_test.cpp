// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "support/input_error_message.h"
#include "support/models_without_zone_outlines.h"
#include "support/test_maps.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/relocalize/relocalizer.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "mrpt_krp_plugin/zones/zone.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

namespace krp {
namespace {

const std::string kModels = std::string(KRP_SOURCE_DIR) + "/models/office_two_zone";
const std::string kWorld = std::string(KRP_SOURCE_DIR) + "/sim_worlds/office_two_zone/office_two_zone.world.yaml";

using test::inputErrorMessage;

using test::modelsWithoutZoneOutlines;

// The shipped office models were trained for omni_12m (360 deg, 12 m) on a 0.05 m map.
TEST(Relocalizer, RefusesScansFromAnotherLidar) {
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  const Relocalizer relocalizer(kModels, *map.grid);
  const auto trial = generateTrial(*map.grid, world.lidar("omni_12m"), TrialParams{}, 5);
  const mrpt::poses::CPose2D pose(trial.truth[0]);
  Rng rng(1);
  const auto own = ScanSimulator(lidarProfileByName("omni_12m")).simulate(*map.grid, pose, rng);
  EXPECT_EQ(inputErrorMessage([&] { relocalizer.relocalize(*own); }), "");
  for (const char* other : {"safety_270", "lds01"}) {
    const auto scan = ScanSimulator(lidarProfileByName(other)).simulate(*map.grid, pose, rng);
    const auto message = inputErrorMessage([&] { relocalizer.relocalize(*scan); });
    EXPECT_NE(message.find("trained for lidar 'omni_12m'"), std::string::npos) << other << ": " << message;
  }
}

TEST(Relocalizer, RefusesAMapOfAnotherCellSize) {
  const auto map = loadOccupancyMap(readWorld(kWorld).map_path);
  mrpt::maps::COccupancyGridMap2D coarse;
  coarse.setSize(map.grid->getXMin(), map.grid->getXMax(), map.grid->getYMin(), map.grid->getYMax(), 0.1f);
  const auto message = inputErrorMessage([&] { Relocalizer(kModels, coarse); });
  EXPECT_NE(message.find("trained on a map of 0.05"), std::string::npos) << message;
}

// A model file that is not the one the manifest describes (another training's copied over it) is
// refused before it runs with this manifest's zones and landmarks; the shipped files pass.
TEST(Relocalizer, RefusesAModelFileTheManifestDoesNotDescribe) {
  namespace fs = std::filesystem;
  const auto map = loadOccupancyMap(readWorld(kWorld).map_path);
  for (const char* file : {"zone_classifier.onnx", "keypoints.onnx"}) {
    const fs::path dir = test::tempDir(std::string("replaced_") + file);
    fs::copy(kModels, dir, fs::copy_options::recursive);
    EXPECT_EQ(inputErrorMessage([&] { Relocalizer(dir.string(), *map.grid); }), "") << file;
    std::ofstream(dir / file, std::ios::binary | std::ios::app) << '\0';  // one byte more
    const auto message = inputErrorMessage([&] { Relocalizer(dir.string(), *map.grid); });
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find("is not the model manifest.json describes"), std::string::npos) << message;
  }
}

// Same cell size, another building: the models' landmarks are not on its walls.
TEST(Relocalizer, RefusesAnotherWorldsMap) {
  const auto warehouse = loadOccupancyMap(
      readWorld(std::string(KRP_SOURCE_DIR) + "/sim_worlds/warehouse/warehouse.world.yaml").map_path);
  const auto message = inputErrorMessage([&] { Relocalizer(kModels, *warehouse.grid); });
  EXPECT_NE(message.find("trained on another map (world 'office_two_zone')"), std::string::npos) << message;
}

TEST(Relocalizer, RefusesZonesThatAreNotTheModels) {
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  auto zones = readZonesYaml(world.zones_path);
  zones[1].name = "lobby";
  const auto message = inputErrorMessage([&] { Relocalizer(kModels, *map.grid, {}, zones); });
  EXPECT_NE(message.find("no zone named 'east_wing'"), std::string::npos) << message;
  EXPECT_TRUE(Relocalizer(kModels, *map.grid).hasZoneSearch());  // the zones beside the shipped models
  const auto bare = modelsWithoutZoneOutlines("zones_not_the_models");
  EXPECT_FALSE(Relocalizer(bare, *map.grid).hasZoneSearch());
  EXPECT_TRUE(Relocalizer(bare, *map.grid, {}, readZonesYaml(world.zones_path)).hasZoneSearch());
}

// krp-train-map copies the zones beside the models and names them in the manifest: the zone
// search then needs no zones from the user. A named file that is missing is an error, unless
// the user gives the zones.
TEST(Relocalizer, ReadsTheZonesBesideTheModels) {
  namespace fs = std::filesystem;
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  const fs::path dir = modelsWithoutZoneOutlines("zones_beside_models");  // zones.yaml named below, but missing
  nlohmann::json manifest = nlohmann::json::parse(std::ifstream(dir / "manifest.json"));
  manifest["zone_outlines"] = {{"file", "zones.yaml"}, {"sha256", "not checked"}};
  std::ofstream(dir / "manifest.json") << manifest.dump();
  EXPECT_NE(inputErrorMessage([&] { Relocalizer(dir.string(), *map.grid); }).find("zones.yaml"), std::string::npos);
  // Zones given by the user are the only source read: the missing file does not matter then.
  EXPECT_TRUE(Relocalizer(dir.string(), *map.grid, {}, readZonesYaml(world.zones_path)).hasZoneSearch());
  fs::copy_file(world.zones_path, dir / "zones.yaml");
  EXPECT_TRUE(Relocalizer(dir.string(), *map.grid).hasZoneSearch());
  RelocalizerParams off;
  off.zone_search.zones = 0;
  EXPECT_FALSE(Relocalizer(dir.string(), *map.grid, off).hasZoneSearch());
}

// Models without zone outlines (trained before krp-train-map kept them, as models/warehouse was)
// lose the zone search unless the user gives the zones: the relocalizer says so, naming the
// world whose zones.yaml it needs, and says nothing when the search is on or asked off.
TEST(Relocalizer, SaysWhyTheZoneSearchIsOff) {
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  const auto bare = modelsWithoutZoneOutlines("zone_search_missing");
  const std::string missing = Relocalizer(bare, *map.grid).zoneSearchMissing();
  EXPECT_NE(missing.find("no zone outlines"), std::string::npos) << missing;
  EXPECT_NE(missing.find("zones.yaml of world 'office_two_zone'"), std::string::npos) << missing;
  EXPECT_EQ(Relocalizer(bare, *map.grid, {}, readZonesYaml(world.zones_path)).zoneSearchMissing(), "");
  RelocalizerParams off;
  off.zone_search.zones = 0;
  EXPECT_EQ(Relocalizer(bare, *map.grid, off).zoneSearchMissing(), "");
  EXPECT_EQ(Relocalizer(kModels, *map.grid).zoneSearchMissing(), "");
}

// With the keypoints switched off (no zone's detections used) only the zone search can answer:
// it runs, stays in the classifier's zone and finds the pose there.
TEST(Relocalizer, ZoneSearchAnswersWhenTheKeypointsGiveNothing) {
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  RelocalizerParams params;
  params.top_zones = 0;
  params.cross_check.when_not_localized = false;  // the zone search's own answer, unchecked
  const auto zones = readZonesYaml(world.zones_path);
  const Relocalizer with_search(kModels, *map.grid, params, zones),
      without(modelsWithoutZoneOutlines("keypoints_give_nothing"), *map.grid, params);
  const ZoneIndex index(*map.grid, zones);
  Rng rng(3);
  int searched = 0, right = 0;
  const int trials = 4;
  for (int i = 0; i < trials; ++i) {
    const auto trial = generateTrial(*map.grid, world.lidar("omni_12m"), TrialParams{}, 20 + i);
    const mrpt::poses::CPose2D truth(trial.truth[0]);
    const auto scan = ScanSimulator(lidarProfileByName("omni_12m")).simulate(*map.grid, truth, rng);
    const auto off = without.relocalize(*scan);
    EXPECT_EQ(off.candidates, 0);
    EXPECT_FALSE(off.ranking.localized);
    EXPECT_FALSE(off.zone_search_used);
    const auto on = with_search.relocalize(*scan);
    ASSERT_TRUE(on.zone_search_used);
    searched += on.zone_search_candidates > 0;
    if (on.ranking.hypotheses.empty()) continue;
    const auto& best = on.ranking.hypotheses.front();
    const int top_zone = static_cast<int>(std::max_element(on.zone_probabilities.begin(), on.zone_probabilities.end()) -
                                          on.zone_probabilities.begin());
    EXPECT_EQ(index.zoneAt({best.pose.x, best.pose.y}), top_zone);
    const bool in_truth_zone = index.zoneAt({truth.x(), truth.y()}) == top_zone;
    if (in_truth_zone && on.ranking.localized)
      right += std::hypot(best.pose.x - truth.x(), best.pose.y - truth.y()) < 0.5;
  }
  EXPECT_EQ(searched, trials);
  EXPECT_GE(right, 1) << "the search of the right zone should find the pose";
}

// With the cross-check on, the keypoint model runs on the next submap turn only while no turn
// so far gave a credible answer, and the cross-check then checks the answer. A scan that needed
// both turns gets the very answer of the relocalizer that always runs both. Without the
// cross-check every turn runs. Seeds 0-5 include scans of either kind.
TEST(Relocalizer, RunsTheNextTurnOnlyWhileNotLocalized) {
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  const auto zones = readZonesYaml(world.zones_path);
  RelocalizerParams stopping;
  RelocalizerParams every_turn = stopping;
  every_turn.stop_turns_once_localized = false;
  RelocalizerParams unchecked = stopping;
  unchecked.cross_check.enabled = false;
  const Relocalizer lazy(kModels, *map.grid, stopping, zones), eager(kModels, *map.grid, every_turn, zones),
      without_check(kModels, *map.grid, unchecked, zones);
  int one_turn = 0, two_turns = 0;
  for (int seed = 0; seed < 6; ++seed) {
    const auto trial = generateTrial(*map.grid, world.lidar("omni_12m"), TrialParams{}, seed);
    Rng rng(seed);
    const auto scan =
        ScanSimulator(lidarProfileByName("omni_12m")).simulate(*map.grid, mrpt::poses::CPose2D(trial.truth[0]), rng);
    const auto a = lazy.relocalize(*scan), b = eager.relocalize(*scan);
    ASSERT_EQ(b.keypoint_turns, stopping.top_turns) << "seed " << seed;
    EXPECT_EQ(without_check.relocalize(*scan).keypoint_turns, stopping.top_turns) << "seed " << seed;
    if (a.keypoint_turns == 1) {
      ++one_turn;
      // Localized after the first turn: no zone search, and the answer was cross-checked.
      EXPECT_FALSE(a.zone_search_used) << "seed " << seed;
      EXPECT_TRUE(a.cross_check_used) << "seed " << seed;
      continue;
    }
    ++two_turns;
    ASSERT_EQ(a.keypoint_turns, 2);
    EXPECT_EQ(a.candidates, b.candidates) << "seed " << seed;
    EXPECT_EQ(a.ranking.localized, b.ranking.localized) << "seed " << seed;
    ASSERT_EQ(a.ranking.hypotheses.size(), b.ranking.hypotheses.size()) << "seed " << seed;
    if (a.ranking.hypotheses.empty()) continue;
    const auto &pa = a.ranking.hypotheses.front().pose, &pb = b.ranking.hypotheses.front().pose;
    EXPECT_DOUBLE_EQ(pa.x, pb.x);
    EXPECT_DOUBLE_EQ(pa.y, pb.y);
    EXPECT_DOUBLE_EQ(pa.phi, pb.phi);
  }
  EXPECT_GT(one_turn, 0);
  EXPECT_GT(two_turns, 0);
}

// The keypoints of the office's look-alike wings sometimes align to the wrong wing, and
// verification alone finds nothing wrong there. The cross-check searches the map for a place
// that fits as well: it turns such answers right or "not localized", and makes no right answer
// wrong. With the shipped office models (16,000 poses per zone), of trial seeds 0-119 the
// keypoints alone were localized but wrong at 55, 68, 83 and 113 in the gcc build and at 13 in
// the clang sanitizer build (borderline scans: floating point differs between the builds); the
// other seeds below were right in both. With the cross-check, and with the fit floor alone, none
// of the 120 was wrong in either build.
TEST(Relocalizer, CrossCheckCatchesTheLookAlikeWing) {
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  const auto zones = readZonesYaml(world.zones_path);
  RelocalizerParams checked, unchecked;
  unchecked.cross_check.enabled = false;
  // What the cross-check does by itself, without the fit floor on "localized" (default 0.9),
  // which on its own leaves none of these wrong (checked below with `floored`).
  const RelocalizerParams floored_params = unchecked;
  checked.verifier.ranking.min_localized_fit_fraction = 0.0;
  unchecked.verifier.ranking.min_localized_fit_fraction = 0.0;
  const Relocalizer floored(kModels, *map.grid, floored_params, zones);
  const Relocalizer with_check(kModels, *map.grid, checked, zones), without(kModels, *map.grid, unchecked, zones);
  auto wrong = [](const RelocalizationResult& r, const mrpt::poses::CPose2D& truth) {
    const auto& best = r.ranking.hypotheses.front().pose;
    return r.ranking.localized && std::hypot(best.x - truth.x(), best.y - truth.y()) >= 0.5;
  };
  int wrong_without = 0, wrong_with = 0, checks = 0;
  for (int seed : {13, 55, 68, 83, 113, 0, 1, 2, 3, 4}) {
    const auto trial = generateTrial(*map.grid, world.lidar("omni_12m"), TrialParams{}, seed);
    const mrpt::poses::CPose2D truth(trial.truth[0]);
    Rng rng(seed);
    const auto scan = ScanSimulator(lidarProfileByName("omni_12m")).simulate(*map.grid, truth, rng);
    const auto off = without.relocalize(*scan), on = with_check.relocalize(*scan);
    EXPECT_FALSE(off.cross_check_used);
    checks += on.cross_check_used;
    const bool w0 = wrong(off, truth), w1 = wrong(on, truth);
    wrong_without += w0;
    wrong_with += w1;
    EXPECT_FALSE(w1) << "seed " << seed;
    EXPECT_FALSE(wrong(floored.relocalize(*scan), truth)) << "seed " << seed;
  }
  EXPECT_GT(checks, 0);
  // Four in the gcc build, one in the clang sanitizer build (above).
  EXPECT_GE(wrong_without, 1) << "the scans were chosen because the keypoints alone get some wrong";
  EXPECT_EQ(wrong_with, 0);
}

// With the 3.5 m lidar a room can fit the scan as well as its twin elsewhere. A place the
// cross-check finds may outrank the answer; checking only the first answer leaves that new best
// unchecked, and its own twin may be the truth. Repeating the check on each new best turns such
// answers into "not localized". Of trial seeds 0-59, 33 and 51 were localized but wrong with one
// round in both the gcc and the clang sanitizer build; repeated rounds fix both in the gcc build
// and 33 in the clang one (there the second check finds no twin for 51: these are borderline
// scans, and floating point differs between the builds). 5 and 53 are localized and right in
// both builds, and must stay so.
TEST(Relocalizer, CrossCheckRepeatsOnANewBestUntilTheAnswerHolds) {
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  const auto zones = readZonesYaml(world.zones_path);
  RelocalizerParams one_round, rounds;
  one_round.cross_check.max_rounds = 1;
  // The fit floor on "localized" is off: this pins what the repeated check does by itself.
  one_round.verifier.ranking.min_localized_fit_fraction = 0.0;
  rounds.verifier.ranking.min_localized_fit_fraction = 0.0;
  const std::string models = std::string(KRP_SOURCE_DIR) + "/models/office_two_zone_lds01";
  const Relocalizer once(models, *map.grid, one_round, zones), repeated(models, *map.grid, rounds, zones);
  int wrong_once = 0, wrong_repeated = 0, right_once = 0, right_repeated = 0, repeats = 0;
  for (int seed : {33, 51, 5, 53}) {
    const auto trial = generateTrial(*map.grid, world.lidar("lds01"), TrialParams{}, seed);
    const mrpt::poses::CPose2D truth(trial.truth[0]);
    Rng rng(seed);
    const auto scan = ScanSimulator(lidarProfileByName("lds01")).simulate(*map.grid, truth, rng);
    const auto a = once.relocalize(*scan), b = repeated.relocalize(*scan);
    EXPECT_EQ(a.cross_check_rounds, 1);
    repeats += b.cross_check_rounds > 1;
    auto localizedWithin = [&](const RelocalizationResult& r, bool right) {
      if (!r.ranking.localized) return false;
      const auto& p = r.ranking.hypotheses.front().pose;
      return (std::hypot(p.x - truth.x(), p.y - truth.y()) < 0.5) == right;
    };
    wrong_once += localizedWithin(a, false);
    wrong_repeated += localizedWithin(b, false);
    right_once += localizedWithin(a, true);
    right_repeated += localizedWithin(b, true);
    if (seed == 33) {
      EXPECT_TRUE(localizedWithin(a, false)) << "one round: localized at the twin";
      EXPECT_FALSE(b.ranking.localized) << "repeated: the twin's own look-alike is found";
    }
  }
  EXPECT_GT(repeats, 0);
  EXPECT_GE(wrong_once, 1) << "the scans were chosen because one round leaves some wrong";
  EXPECT_LT(wrong_repeated, wrong_once);
  EXPECT_EQ(right_repeated, right_once) << "no right answer lost";
}

// The zone search looks in the classifier's zone only; when the classifier names the look-alike
// wing, the true place is never proposed there. Here the zone search is made to look in the
// other wing whatever the classifier says (both zone names given that wing's outline) and the
// keypoints are off: the check of the not-localized best finds the true place anyway.
TEST(Relocalizer, CrossCheckFindsThePlaceTheZoneSearchMissed) {
  const auto world = readWorld(kWorld);
  const auto map = loadOccupancyMap(world.map_path);
  const auto zones = readZonesYaml(world.zones_path);
  const ZoneIndex index(*map.grid, zones);
  RelocalizerParams checked;
  checked.top_zones = 0;
  RelocalizerParams unchecked = checked;
  unchecked.cross_check.enabled = false;
  auto onlyThisWing = [&](size_t wing) {
    auto misnamed = zones;
    for (auto& z : misnamed) z.polygon = zones[wing].polygon;
    return misnamed;
  };
  int right_with = 0, right_without = 0, rescued_not_localized = 0;
  const int trials = 4;
  for (int seed = 0; seed < trials; ++seed) {
    const auto trial = generateTrial(*map.grid, world.lidar("omni_12m"), TrialParams{}, 30 + seed);
    const mrpt::poses::CPose2D truth(trial.truth[0]);
    const int truth_zone = index.zoneAt({truth.x(), truth.y()});
    ASSERT_GE(truth_zone, 0);
    const auto other_wing = onlyThisWing(truth_zone == 0 ? 1 : 0);
    const Relocalizer with_check(kModels, *map.grid, checked, other_wing),
        without(kModels, *map.grid, unchecked, other_wing);
    Rng rng(seed);
    const auto scan = ScanSimulator(lidarProfileByName("omni_12m")).simulate(*map.grid, truth, rng);
    auto right = [&](const RelocalizationResult& r) {
      if (r.ranking.hypotheses.empty()) return false;
      const auto& best = r.ranking.hypotheses.front().pose;
      return std::hypot(best.x - truth.x(), best.y - truth.y()) < 0.5;
    };
    const auto off = without.relocalize(*scan), on = with_check.relocalize(*scan);
    EXPECT_TRUE(off.zone_search_used);
    EXPECT_FALSE(off.cross_check_used);
    EXPECT_TRUE(on.cross_check_used) << "seed " << seed;
    right_without += right(off);
    right_with += right(on);
    rescued_not_localized += !off.ranking.localized && right(on);
  }
  EXPECT_EQ(right_without, 0) << "the true place lies outside the searched wing";
  EXPECT_GE(right_with, trials - 1);
  // The zone search finds the mirror place credible for some scans (then the check of a
  // localized answer would run anyway); the others are the ones this check exists for.
  EXPECT_GE(rescued_not_localized, 1);
}

}  // namespace
}  // namespace krp
