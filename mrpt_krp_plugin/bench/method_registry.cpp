// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/method_registry.h"

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

std::vector<std::string> methodNames() {
  return {"uniform-mcl", "amcl-kld", "amcl-kld-50k", "seeded", "seeded-no-uniform", "seeded-keypoints-only",
          "global-matcher"};
}

bool methodNeedsKeypointsOnly(const std::string& name) { return name == "seeded-keypoints-only"; }
bool methodNeedsModels(const std::string& name) {
  return name == "seeded" || name == "seeded-no-uniform" || methodNeedsKeypointsOnly(name);
}
bool methodNeedsMatcher(const std::string& name) { return name == "global-matcher"; }

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
    const auto relocalizer = methodNeedsKeypointsOnly(name) ? resources.keypoints_only_relocalizer : resources.relocalizer;
    if (!relocalizer) throw InputError("method '" + name + "'", "needs trained models (a models folder with manifest.json)");
    if (name == "seeded-no-uniform") seeded.uniform_fraction = 0.0;
    return std::make_shared<SeededInitializer>(
        [relocalizer](const mrpt::obs::CObservation2DRangeScan& scan) { return relocalizer->relocalize(scan).ranking; },
        seeded, name);
  }
  if (methodNeedsMatcher(name)) {
    const auto matcher = resources.matcher;
    if (!matcher) throw InputError("method '" + name + "'", "needs the map's global matcher");
    return std::make_shared<SeededInitializer>(
        [matcher](const mrpt::obs::CObservation2DRangeScan& scan) { return matcher->relocalize(scan); }, seeded, name);
  }
  std::string known;
  for (const auto& n : methodNames()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("method '" + name + "'", "unknown (known: " + known + ")");
}

}  // namespace krp
