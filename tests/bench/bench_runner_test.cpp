// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/bench_runner.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "mrpt_krp_plugin/bench/method_registry.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/inference/model_manifest.h"
#include "mrpt_krp_plugin/sim/world.h"

namespace krp {
namespace {

BenchConfig smallOfficeRun() {
  BenchConfig cfg;
  cfg.world_files = {std::string(KRP_SOURCE_DIR) + "/sim_worlds/office_two_zone/office_two_zone.world.yaml"};
  cfg.methods = {"amcl-kld"};
  cfg.trials = 3;
  cfg.trial.steps = 2;
  cfg.seed = 11;
  return cfg;
}

// A trial replayed alone (--only-trials) is the trial of the full run: same seeds, same outcome.
TEST(BenchRunner, OneTrialReplayedAloneMatchesTheFullRun) {
  std::ostringstream log;
  const auto full = runBench(smallOfficeRun(), log);
  ASSERT_EQ(full.size(), 3u);
  auto cfg = smallOfficeRun();
  cfg.only_trials = {2};
  const auto alone = runBench(cfg, log);
  ASSERT_EQ(alone.size(), 1u);
  const auto& a = alone.front();
  const auto& f = full[2];
  EXPECT_EQ(a.trial, 2);
  EXPECT_EQ(a.trial_seed, f.trial_seed);
  EXPECT_EQ(a.filter_seed, f.filter_seed);
  ASSERT_EQ(a.updates.size(), f.updates.size());
  for (size_t i = 0; i < a.updates.size(); ++i) {
    EXPECT_DOUBLE_EQ(a.updates[i].error_xy_m, f.updates[i].error_xy_m) << "update " << i;
    EXPECT_DOUBLE_EQ(a.updates[i].error_phi_deg, f.updates[i].error_phi_deg) << "update " << i;
  }
  EXPECT_NE(full[0].trial_seed, full[2].trial_seed);  // the replay did not just run trial 0 again
}

TEST(BenchRunner, RefusesATrialOutsideTheRun) {
  auto cfg = smallOfficeRun();
  cfg.only_trials = {3};
  std::ostringstream log;
  EXPECT_THROW(runBench(cfg, log), InputError);
  cfg.only_trials = {-1};
  EXPECT_THROW(runBench(cfg, log), InputError);
}

// The baselines weigh particles as amcl does (likelihood field alone); the guarded methods add
// the see-through penalty. The same run with the penalty switched off for every method gives
// the guarded method the baselines' model.
TEST(BenchRunner, OnlyTheGuardedMethodsChargeBeamsSeenThroughTheMap) {
  for (const char* baseline : {"uniform-mcl", "amcl-kld", "amcl-kld-50k", "global-matcher", "seeded-no-guard"})
    EXPECT_FALSE(methodUsesSeeThrough(baseline)) << baseline;
  for (const char* guarded : {"seeded", "seeded-no-uniform", "global-matcher-guarded"})
    EXPECT_TRUE(methodUsesSeeThrough(guarded)) << guarded;
  auto cfg = smallOfficeRun();
  cfg.methods = {"global-matcher-guarded"};
  cfg.trials = 1;
  std::ostringstream log;
  const auto charged = runBench(cfg, log);
  cfg.mcl.see_through.enabled = false;
  const auto field_only = runBench(cfg, log);
  ASSERT_EQ(charged.size(), 1u);
  ASSERT_EQ(field_only.size(), 1u);
  bool differ = false;
  for (size_t i = 0; i < charged[0].updates.size(); ++i)
    differ |= charged[0].updates[i].error_xy_m != field_only[0].updates[i].error_xy_m;
  EXPECT_TRUE(differ) << "the penalty changed the particles' weights";
}

// A report names the models its seeded methods ran (folder and sha256), so one made before the
// models were replaced says so; the methods without models name none.
TEST(BenchRunner, RecordsNameTheModelsTheSeededMethodsRan) {
  auto cfg = smallOfficeRun();
  cfg.methods = {"amcl-kld", "seeded-keypoints-only"};
  cfg.trials = 1;
  cfg.trial.steps = 1;
  cfg.method_settings.models_root = std::string(KRP_SOURCE_DIR) + "/models";
  std::ostringstream log;
  const auto records = runBench(cfg, log);
  ASSERT_EQ(records.size(), 2u);
  const auto manifest = readModelManifest(cfg.method_settings.models_root + "/office_two_zone");
  for (const auto& r : records) {
    if (r.method == "amcl-kld") {
      EXPECT_EQ(r.models, "");
      continue;
    }
    EXPECT_NE(r.models.find("office_two_zone (classifier sha256 " + manifest.classifier.sha256.substr(0, 12)),
              std::string::npos)
        << r.models;
    EXPECT_NE(r.models.find("keypoints sha256 " + manifest.keypoints.sha256.substr(0, 12)), std::string::npos)
        << r.models;
  }
}

// A world drawn on another world's map (the cluttered office) has no models folder of its own:
// the error names the folder of models trained on its map for its lidar, and none of another
// map's or another lidar's.
TEST(BenchRunner, AWorldWithoutModelsIsPointedAtTheModelsOfItsMap) {
  const std::string root = std::string(KRP_SOURCE_DIR) + "/models";
  const World cluttered =
      readWorld(std::string(KRP_SOURCE_DIR) + "/sim_worlds/office_cluttered/office_cluttered.world.yaml");
  EXPECT_EQ(modelsOfTheSameMap(root, cluttered, "omni_12m"), std::vector<std::string>{root + "/office_two_zone"});
  EXPECT_EQ(modelsOfTheSameMap(root, cluttered, "lds01"), std::vector<std::string>{root + "/office_two_zone_lds01"});
  const World warehouse = readWorld(std::string(KRP_SOURCE_DIR) + "/sim_worlds/warehouse/warehouse.world.yaml");
  EXPECT_EQ(modelsOfTheSameMap(root, warehouse, "omni_12m"), std::vector<std::string>{root + "/warehouse"});
  EXPECT_TRUE(modelsOfTheSameMap(root + "/no_such_folder", cluttered, "omni_12m").empty());
  try {
    modelsFolder(root, {}, cluttered, "omni_12m");
    FAIL() << "a world without models was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("krp-train-map --world office_cluttered"), std::string::npos) << what;
    EXPECT_NE(what.find("--models-for office_cluttered=" + root + "/office_two_zone"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace krp
