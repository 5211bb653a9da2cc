// SPDX-License-Identifier: BSD-3-Clause
// The documented parameter file and the node must list the same keys, with the same defaults.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <set>

#include "node_params.h"

namespace krp::ros1 {
namespace {

TEST(RosNodeParams, TheYamlDocumentsExactlyTheNodesKeys) {
  const YAML::Node doc = YAML::LoadFile(KRP_ROS1_DIR "/config/krp_relocalizer.yaml");
  std::set<std::string> documented;
  for (const auto& kv : doc) documented.insert(kv.first.as<std::string>());
  const auto names = nodeParamNames();
  EXPECT_EQ(documented, std::set<std::string>(names.begin(), names.end()));
}

TEST(RosNodeParams, TheYamlDefaultsAreTheNodesDefaults) {
  const YAML::Node doc = YAML::LoadFile(KRP_ROS1_DIR "/config/krp_relocalizer.yaml");
  const NodeParams d;
  EXPECT_EQ(doc["backend"].as<std::string>(), d.backend);
  EXPECT_EQ(doc["mode"].as<std::string>(), d.mode);
  EXPECT_EQ(doc["map_file"].as<std::string>(), d.map_file);
  EXPECT_EQ(doc["relocalize_on_startup"].as<bool>(), d.relocalize_on_startup);
  EXPECT_EQ(doc["relocalize_on_kidnap"].as<bool>(), d.relocalize_on_kidnap);
  EXPECT_EQ(doc["publish_when_not_localized"].as<bool>(), d.publish_when_not_localized);
  EXPECT_EQ(doc["min_valid_returns"].as<int>(), d.min_valid_returns);
  EXPECT_EQ(doc["top_turns"].as<int>(), d.top_turns);
  EXPECT_EQ(doc["stop_turns_once_localized"].as<bool>(), d.stop_turns_once_localized);
  EXPECT_EQ(doc["search_zones"].as<int>(), d.search_zones);
  EXPECT_DOUBLE_EQ(doc["wall_heading_window_deg"].as<double>(), d.wall_heading_window_deg);
  EXPECT_EQ(doc["max_particles"].as<int>(), d.max_particles);
  EXPECT_DOUBLE_EQ(doc["max_scan_age_s"].as<double>(), d.max_scan_age_s);
  EXPECT_DOUBLE_EQ(doc["trigger_timeout_s"].as<double>(), d.trigger_timeout_s);
  EXPECT_DOUBLE_EQ(doc["update_min_d"].as<double>(), d.update_min_d);
  EXPECT_DOUBLE_EQ(doc["update_min_a"].as<double>(), d.update_min_a);
  EXPECT_DOUBLE_EQ(doc["uniform_fraction"].as<double>(), d.uniform_fraction);
  EXPECT_EQ(doc["shrink_uniform_start"].as<bool>(), d.shrink_uniform_start);
  EXPECT_DOUBLE_EQ(doc["look_alike_ambiguity_margin"].as<double>(), d.look_alike_ambiguity_margin);
  EXPECT_DOUBLE_EQ(doc["look_alike_min_fit_fraction"].as<double>(), d.look_alike_min_fit_fraction);
  EXPECT_EQ(doc["look_alike_watch_rejected"].as<bool>(), d.look_alike_watch_rejected);
  EXPECT_EQ(doc["look_alike_unverified_is_unsettled"].as<bool>(), d.look_alike_unverified_is_unsettled);
  EXPECT_EQ(doc["see_through_penalty"].as<bool>(), d.see_through_penalty);
  EXPECT_EQ(doc["look_alike_search_charges_see_through"].as<bool>(), d.look_alike_search_charges_see_through);
  EXPECT_EQ(doc["look_alike_refit_charges_see_through"].as<bool>(), d.look_alike_refit_charges_see_through);
  EXPECT_EQ(doc["look_alike_rival_refinements"].as<int>(), d.look_alike_rival_refinements);
  EXPECT_EQ(doc["look_alike_max_search_nodes"].as<int>(), d.look_alike_max_search_nodes);
  EXPECT_EQ(doc["look_alike_max_nodes_per_update"].as<int>(), d.look_alike_max_nodes_per_update);
  EXPECT_EQ(doc["look_alike_history_updates"].as<int>(), d.look_alike_history_updates);
  EXPECT_EQ(doc["look_alike_recheck_every_updates"].as<int>(), d.look_alike_recheck_every_updates);
  EXPECT_DOUBLE_EQ(doc["transform_tolerance_s"].as<double>(), d.transform_tolerance_s);
  EXPECT_DOUBLE_EQ(doc["transform_timeout_s"].as<double>(), d.transform_timeout_s);
  EXPECT_EQ(doc["global_frame"].as<std::string>(), d.global_frame);
  EXPECT_EQ(doc["odom_frame"].as<std::string>(), d.odom_frame);
  EXPECT_EQ(doc["base_frame"].as<std::string>(), d.base_frame);
}

// What the node hands its filter: the switch and the kidnap detector, nothing else changed.
TEST(RosNodeParams, TheFilterGetsTheSeeThroughSwitchAndTheKidnapDetector) {
  NodeParams p;
  EXPECT_TRUE(p.mcl().see_through.enabled);
  p.see_through_penalty = false;
  p.relocalize_on_kidnap = true;
  const auto mcl = p.mcl();
  EXPECT_FALSE(mcl.see_through.enabled);
  EXPECT_TRUE(mcl.kidnap.enabled);
  EXPECT_EQ(mcl.sensor, MclParams{}.sensor);
}

// What the node hands its look-alike guard: the see-through charges of its search and of its
// rival test's re-fit and its finer grids, the search's node budget, how often it searches again
// and the scan history.
TEST(RosNodeParams, TheGuardGetsTheChargeSwitchesAndItsBudget) {
  NodeParams p;
  EXPECT_TRUE(p.lookAlikeGuard().search_charges_see_through);
  EXPECT_TRUE(p.lookAlikeGuard().rival_test.refit_charges_see_through);
  EXPECT_EQ(p.lookAlikeGuard().max_search_nodes, LookAlikeGuardParams{}.max_search_nodes);
  EXPECT_EQ(p.lookAlikeGuard().rival_test.finer_refinements, RivalTestParams{}.finer_refinements);
  EXPECT_EQ(p.lookAlikeGuard().max_nodes_per_update, NodeParams::kNodeMaxNodesPerUpdate);
  EXPECT_GT(NodeParams::kNodeMaxNodesPerUpdate, 0) << "a live robot's updates must not stall on one search";
  EXPECT_EQ(p.lookAlikeGuard().history_updates, 0);
  EXPECT_EQ(p.lookAlikeGuard().recheck_every_updates, LookAlikeGuardParams{}.recheck_every_updates);
  p.look_alike_history_updates = 10;
  p.look_alike_recheck_every_updates = 5;
  p.look_alike_search_charges_see_through = false;
  p.look_alike_refit_charges_see_through = false;
  p.look_alike_rival_refinements = 0;
  p.look_alike_max_search_nodes = 0;
  p.look_alike_max_nodes_per_update = 0;
  p.look_alike_unverified_is_unsettled = false;
  const auto g = p.lookAlikeGuard();
  EXPECT_FALSE(g.unverified_is_unsettled);
  EXPECT_FALSE(g.search_charges_see_through);
  EXPECT_FALSE(g.rival_test.refit_charges_see_through);
  EXPECT_EQ(g.rival_test.finer_refinements, 0);
  EXPECT_EQ(g.max_search_nodes, 0);
  EXPECT_EQ(g.max_nodes_per_update, 0);
  EXPECT_EQ(g.history_updates, 10);
  EXPECT_EQ(g.recheck_every_updates, 5);
}

TEST(RosNodeParams, TheTurnAndZoneSearchSettingsReachTheLearnedRelocalizer) {
  NodeParams p;
  p.top_turns = 4;
  p.stop_turns_once_localized = false;
  p.search_zones = 3;
  p.wall_heading_window_deg = 0.0;
  const auto h = p.hypothesisSource();
  EXPECT_EQ(h.learned.zone_search.zones, 3);
  EXPECT_EQ(h.learned.wall_heading_window_deg, 0.0);
  EXPECT_EQ(NodeParams{}.hypothesisSource().learned.wall_heading_window_deg, RelocalizerParams{}.wall_heading_window_deg);
  EXPECT_EQ(h.learned.top_turns, 4);
  EXPECT_FALSE(h.learned.stop_turns_once_localized);
  EXPECT_EQ(NodeParams{}.hypothesisSource().learned.top_turns, RelocalizerParams{}.top_turns);
}

// The uniform start's shrinking follows the node's switch, down to the node's seeded floor
// (which max_particles may lower).
TEST(RosNodeParams, TheUniformStartShrinksToTheNodesSeededFloor) {
  NodeParams p;
  EXPECT_TRUE(p.seeded().fallback_shrinks.has_value());
  p.max_particles = 300;
  EXPECT_EQ(p.seeded().min_particles, 300u) << "the floor a uniform start shrinks to";
  p.shrink_uniform_start = false;
  EXPECT_FALSE(p.seeded().fallback_shrinks.has_value());
}

}  // namespace
}  // namespace krp::ros1
