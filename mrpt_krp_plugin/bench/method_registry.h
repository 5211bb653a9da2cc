// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/filter/amcl_kld_initializer.h"
#include "mrpt_krp_plugin/filter/look_alike_guard.h"
#include "mrpt_krp_plugin/filter/seeded_initializer.h"
#include "mrpt_krp_plugin/filter/uniform_initializer.h"
#include "mrpt_krp_plugin/relocalize/matcher_relocalizer.h"
#include "mrpt_krp_plugin/relocalize/relocalizer.h"
#include "mrpt_krp_plugin/sim/world.h"

namespace krp {

/// Settings of every method the bench knows, so one flag set configures them all.
struct MethodSettings {
  UniformInitParams uniform;
  AmclKldParams amcl;
  std::size_t amcl_high_max_particles = 50000;  ///< `amcl-kld-50k`: amcl with a raised max
  SeededInitParams seeded;
  RelocalizerParams relocalizer;
  /// The seeded methods read their models from modelsFolder() under this (krp-train-map's output).
  std::string models_root = "models";
  /// Worlds whose models are elsewhere, by world name: a changed world (clutter, an unseen wing)
  /// run with the models of the map it changes.
  std::map<std::string, std::string> models_by_world;
  MatcherRelocalizerParams matcher;
  LookAlikeGuardParams guard;  ///< the filter's check of each convergence (methodUsesLookAlikeGuard)
};

/// What some methods need built once per map: the learned relocalizer of each seeded method
/// (made with relocalizerParamsFor(), and with the zones' outlines where it uses them) and the
/// global correlative matcher (`global-matcher`).
struct MethodResources {
  std::map<std::string, std::shared_ptr<const Relocalizer>> relocalizers;  ///< by method name
  std::shared_ptr<const MatcherRelocalizer> matcher;
  std::shared_ptr<const LookAlikeGuard> guard;  ///< for the methods whose filter checks its convergence
  /// The filter map's free cells, for the seeded methods' uniform share (SeededInitializer::useFreeCells).
  std::shared_ptr<const FreeCells> free_cells;
};

/// The method names: `uniform-mcl`, `amcl-kld`, `amcl-kld-50k`, `seeded`, `seeded-no-uniform`,
/// `seeded-no-cross-check` (no check of the best answer for look-alike places),
/// `seeded-no-guard` (the filter does not check its convergence for look-alike places),
/// `seeded-keypoints-only` (what the two models and the verification achieve on their own: no
/// zone search, no cross-check, no guard), `seeded-spread-count` (`seeded` with its particle
/// count from the hypotheses' spread: SeededInitParams::count_from_spread), `seeded-later-scans`
/// (`seeded` whose filter, while unsure of its pose, relocalizes later scans and gives their
/// hypotheses particles: MclParams::later_scans), `global-matcher`,
/// `global-matcher-guarded` (the
/// same with the look-alike guard: the ROS node's track mode with its default backend).
std::vector<std::string> methodNames();

/// Whether the method needs trained models (a Relocalizer).
bool methodNeedsModels(const std::string& name);
/// Whether its relocalizer searches zones, so needs the zones' outlines.
bool methodUsesZoneSearch(const std::string& name);
/// The relocalizer parameters of a seeded method: `base` with what the method turns off.
RelocalizerParams relocalizerParamsFor(const std::string& name, RelocalizerParams base);
/// Whether the method's filter checks each convergence for a look-alike place (LookAlikeGuard):
/// the seeded methods but `seeded-no-guard` and `seeded-keypoints-only`, and
/// `global-matcher-guarded`.
bool methodUsesLookAlikeGuard(const std::string& name);
/// The method weighs particles with the see-through penalty (MclParams::see_through) on top of
/// the likelihood field: the guarded ones. The others weigh them as amcl does.
bool methodUsesSeeThrough(const std::string& name);
/// The look-alike guard of a map, with its own correlative matcher (the relocalizer's matcher
/// settings) and `settings.guard`.
std::shared_ptr<const LookAlikeGuard> makeLookAlikeGuard(const mrpt::maps::COccupancyGridMap2D& map,
                                                         const MethodSettings& settings);
/// Whether the method's filter relocalizes later scans while unsure (MclParams::later_scans):
/// `seeded-later-scans`.
bool methodSeedsFromLaterScans(const std::string& name);
/// Whether the method needs the global matcher.
bool methodNeedsMatcher(const std::string& name);

/// Where the seeded methods find a world's models for a lidar: `<root>/<world>` for the world's
/// default lidar, `<root>/<world>_<lidar>` for another (krp-train-map --world W --lidar L --out
/// <root>/W_L), unless `by_world` names a folder for the world. InputError naming the folder
/// (and the training command) when it holds no models.
std::string modelsFolder(const std::string& root, const std::map<std::string, std::string>& by_world,
                         const World& world, const std::string& lidar);

/// The model folders directly under `root` trained on `world`'s map (requireTrainingMap passes)
/// for `lidar`, sorted: for a world drawn on another world's map (clutter added, a wing closed
/// off) whose own folder is missing, modelsFolder()'s error names them. Empty when none, or when
/// the root or the map cannot be read.
std::vector<std::string> modelsOfTheSameMap(const std::string& root, const World& world, const std::string& lidar);

/// A fresh initializer for a method; InputError listing the names for an unknown one, or for a
/// method whose resources are missing.
std::shared_ptr<ParticleInitializer> makeInitializer(const std::string& name, const MethodSettings& settings,
                                                     const MethodResources& resources = {});

}  // namespace krp
