// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/inference/model_manifest.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_source.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "support/models_without_zone_outlines.h"
#include "support/test_maps.h"

namespace krp {
namespace {

std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> room() {
  return std::make_shared<const mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
}

TEST(HypothesisSource, GlobalMatcherNeedsNoModelsAndFindsThePose) {
  HypothesisSourceParams p;
  p.backend = "global-matcher";
  const auto map = room();
  const auto source = makeHypothesisSource(map, p);
  Rng rng(3);
  const mrpt::poses::CPose2D truth(5.5, 2.1, 0.8);
  const auto scan = ScanSimulator(lidarProfileByName("omni_12m")).simulate(*map, truth, rng);
  const Ranking r = source(*scan);
  ASSERT_FALSE(r.hypotheses.empty());
  EXPECT_NEAR(r.hypotheses[0].pose.x, truth.x(), 0.15);
  EXPECT_NEAR(r.hypotheses[0].pose.y, truth.y(), 0.15);
}

// A status line says what runs: the matcher, or the models by folder and sha256.
TEST(HypothesisSource, DescribesWhatRuns) {
  HypothesisSourceParams p;
  p.backend = "global-matcher";
  std::string description;
  makeHypothesisSource(room(), p, &description);
  EXPECT_EQ(description, "global-matcher");
  p.backend = "learned";
  p.models_dir = std::string(KRP_SOURCE_DIR) + "/models/office_two_zone";
  const auto office = loadOccupancyMap(std::string(KRP_SOURCE_DIR) + "/sim_worlds/office_two_zone/office_two_zone.yaml");
  std::string warning = "left from before";
  makeHypothesisSource(office.grid, p, &description, &warning);
  EXPECT_EQ(description, "learned, " + modelsIdentity(readModelManifest(p.models_dir)));
  EXPECT_EQ(warning, "");
  EXPECT_NE(description.find("classifier sha256 "), std::string::npos) << description;
  // Models without zone outlines, and no zones given: a warning that the zone search is off.
  p.models_dir = test::modelsWithoutZoneOutlines("source_models_without_zones");
  makeHypothesisSource(office.grid, p, &description, &warning);
  EXPECT_EQ(description, "learned, " + modelsIdentity(readModelManifest(p.models_dir)));
  EXPECT_NE(warning.find("the models in " + p.models_dir), std::string::npos) << warning;
  EXPECT_NE(warning.find("zone search is off"), std::string::npos) << warning;
}

TEST(HypothesisSource, LearnedWithoutModelsSaysWhatIsMissing) {
  HypothesisSourceParams p;
  p.backend = "learned";
  try {
    makeHypothesisSource(room(), p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("models folder"), std::string::npos) << e.what();
  }
}

TEST(HypothesisSource, UnknownBackendListsTheKnownOnes) {
  HypothesisSourceParams p;
  p.backend = "magic";
  try {
    makeHypothesisSource(room(), p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("global-matcher"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace krp
