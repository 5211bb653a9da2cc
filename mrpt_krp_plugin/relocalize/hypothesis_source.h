// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "mrpt_krp_plugin/relocalize/confidence_calibration.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_ranking.h"
#include "mrpt_krp_plugin/relocalize/matcher_relocalizer.h"
#include "mrpt_krp_plugin/relocalize/relocalizer.h"

namespace krp {

/// One scan -> ranked robot-pose hypotheses in the map's grid frame. Safe to call from one
/// thread at a time; it keeps whatever it needs (map, models) alive itself.
using HypothesisSource = std::function<Ranking(const mrpt::obs::CObservation2DRangeScan&)>;

/// Where hypotheses come from, for applications that let the user choose:
///   `learned`         the zone classifier + keypoint model of `models_dir` (Relocalizer);
///   `global-matcher`  the exhaustive correlative matcher over the whole map (no models).
struct HypothesisSourceParams {
  std::string backend = "learned";
  std::string models_dir;  ///< needed by `learned`
  /// `learned`, optional: the zones.yaml the models were trained on, which enables the
  /// relocalizer's zone search (ZoneSearchParams) when the keypoints give no credible pose.
  std::string zones_file;
  RelocalizerParams learned;
  MatcherRelocalizerParams matcher;
};

/// A map's fitted confidence calibration (krp-bench --fit-calibration) for both backends' rankings.
void useConfidenceCalibration(const ConfidenceCalibration& calibration, RelocalizerParams& learned,
                              MatcherRelocalizerParams& matcher);

/// Sets the ranking's min_localized_fit_fraction in both backends' parameters.
void useMinLocalizedFitFraction(double fraction, RelocalizerParams& learned, MatcherRelocalizerParams& matcher);

/// Sets CorrelativeMatcherParams::roots_across_headings in both backends' matchers (false: the
/// search's root order before commit 61986f2, to trace a trial that moved with it).
void useMatcherRootsAcrossHeadings(bool across, RelocalizerParams& learned, MatcherRelocalizerParams& matcher);

/// The backend names accepted by makeHypothesisSource, in a stable order.
std::vector<std::string> hypothesisSourceBackends();

/// Builds the chosen backend for `map` (loading models, precomputing search grids: seconds on
/// a large map). InputError for an unknown backend, a missing models_dir for `learned`, or
/// models that do not fit the map. `description`, when given, receives what runs: `learned,
/// <modelsIdentity>` (the folder and its models' sha256) or `global-matcher`, for a status line.
/// `warning`, when given, receives what the user should hear about the source built, or empty:
/// for `learned`, Relocalizer::zoneSearchMissing() (the zone search off for want of zones).
HypothesisSource makeHypothesisSource(std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map,
                                      const HypothesisSourceParams& params, std::string* description = nullptr,
                                      std::string* warning = nullptr);

}  // namespace krp
