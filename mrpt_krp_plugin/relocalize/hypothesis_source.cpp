// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/hypothesis_source.h"

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

namespace krp {

void useConfidenceCalibration(const ConfidenceCalibration& calibration, RelocalizerParams& learned,
                              MatcherRelocalizerParams& matcher) {
  learned.verifier.ranking.calibration = calibration;
  matcher.verifier.ranking.calibration = calibration;
}

void useMinLocalizedFitFraction(double fraction, RelocalizerParams& learned, MatcherRelocalizerParams& matcher) {
  learned.verifier.ranking.min_localized_fit_fraction = fraction;
  matcher.verifier.ranking.min_localized_fit_fraction = fraction;
}

void useMatcherRootsAcrossHeadings(bool across, RelocalizerParams& learned, MatcherRelocalizerParams& matcher) {
  learned.matcher.roots_across_headings = across;
  matcher.matcher.roots_across_headings = across;
}

std::vector<std::string> hypothesisSourceBackends() { return {"learned", "global-matcher"}; }

HypothesisSource makeHypothesisSource(std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map,
                                      const HypothesisSourceParams& params, std::string* description,
                                      std::string* warning) {
  if (warning) warning->clear();
  if (!map) throw InputError("hypothesis source", "no map");
  if (params.backend == "learned") {
    if (params.models_dir.empty())
      throw InputError("hypothesis source 'learned'", "needs a models folder (manifest.json + ONNX models)");
    auto relocalizer = params.zones_file.empty()
                           ? std::make_shared<const Relocalizer>(params.models_dir, *map, params.learned)
                           : std::make_shared<const Relocalizer>(params.models_dir, *map, params.learned,
                                                                 readZonesYaml(params.zones_file));
    if (description) *description = "learned, " + modelsIdentity(relocalizer->manifest());
    if (warning) *warning = relocalizer->zoneSearchMissing();
    // The map is captured too: the relocalizer's verifier was built from it.
    return [relocalizer, map](const mrpt::obs::CObservation2DRangeScan& scan) {
      return relocalizer->relocalize(scan).ranking;
    };
  }
  if (params.backend == "global-matcher") {
    auto matcher = std::make_shared<const MatcherRelocalizer>(*map, params.matcher);
    if (description) *description = "global-matcher";
    return [matcher, map](const mrpt::obs::CObservation2DRangeScan& scan) { return matcher->relocalize(scan); };
  }
  std::string known;
  for (const auto& b : hypothesisSourceBackends()) known += (known.empty() ? "" : ", ") + b;
  throw InputError("hypothesis source", "unknown backend '" + params.backend + "' (known: " + known + ")");
}

}  // namespace krp
