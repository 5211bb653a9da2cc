// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/filter/amcl_kld_initializer.h"
#include "mrpt_krp_plugin/filter/seeded_initializer.h"
#include "mrpt_krp_plugin/filter/uniform_initializer.h"
#include "mrpt_krp_plugin/relocalize/matcher_relocalizer.h"
#include "mrpt_krp_plugin/relocalize/relocalizer.h"

namespace krp {

/// Settings of every method the bench knows, so one flag set configures them all.
struct MethodSettings {
  UniformInitParams uniform;
  AmclKldParams amcl;
  std::size_t amcl_high_max_particles = 50000;  ///< `amcl-kld-50k`: amcl with a raised max
  SeededInitParams seeded;
  RelocalizerParams relocalizer;
  /// The seeded methods read `<models_root>/<world name>/manifest.json` (krp-train-map's output).
  std::string models_root = "models";
  MatcherRelocalizerParams matcher;
};

/// What some methods need built once per map: the learned relocalizer (seeded methods; with the
/// zones' outlines, so with its zone search), the same without zone search
/// (`seeded-keypoints-only`) and the global correlative matcher (`global-matcher`).
struct MethodResources {
  std::shared_ptr<const Relocalizer> relocalizer;
  std::shared_ptr<const MatcherRelocalizer> matcher;
  std::shared_ptr<const Relocalizer> keypoints_only_relocalizer;
};

/// The method names: `uniform-mcl`, `amcl-kld`, `amcl-kld-50k`, `seeded`, `seeded-no-uniform`,
/// `seeded-keypoints-only` (what the two models and the verification achieve on their own, with
/// no zone search), `global-matcher`.
std::vector<std::string> methodNames();

/// Whether the method needs trained models (a Relocalizer).
bool methodNeedsModels(const std::string& name);
/// Whether it needs the relocalizer without zone search (MethodResources::keypoints_only_relocalizer).
bool methodNeedsKeypointsOnly(const std::string& name);
/// Whether the method needs the global matcher.
bool methodNeedsMatcher(const std::string& name);

/// A fresh initializer for a method; InputError listing the names for an unknown one, or for a
/// method whose resources are missing.
std::shared_ptr<ParticleInitializer> makeInitializer(const std::string& name, const MethodSettings& settings,
                                                     const MethodResources& resources = {});

}  // namespace krp
