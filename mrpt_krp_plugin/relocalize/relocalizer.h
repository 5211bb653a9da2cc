// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/inference/keypoint_detector.h"
#include "mrpt_krp_plugin/inference/model_manifest.h"
#include "mrpt_krp_plugin/inference/zone_classifier.h"
#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"
#include "mrpt_krp_plugin/relocalize/keypoint_hypotheses.h"
#include "mrpt_krp_plugin/relocalize/pose_verifier.h"
#include "mrpt_krp_plugin/relocalize/relocalization_times.h"
#include "mrpt_krp_plugin/relocalize/training_map_check.h"
#include "mrpt_krp_plugin/zones/zone.h"

namespace krp {

/// The fallback for a scan whose keypoints give no credible pose: the correlative matcher searches
/// the classifier's most likely zones only, a fraction of the cost of searching the whole map.
/// Needs the zones' outlines (the Relocalizer constructor that takes zones).
struct ZoneSearchParams {
  /// The classifier's most likely zones searched (0 = no zone search); the others stay the
  /// keypoints' business.
  int zones = 1;
};

/// A check of the best answer for look-alike places. The keypoints propose poses only
/// where the models recognise landmarks; when they align to a look-alike (the other wing of a
/// mirror-like building), verification finds nothing wrong with the answer, and the true pose
/// was never proposed. The matcher then searches the whole map with the answer's own score as
/// the bar: branches that cannot reach it are pruned unscored, so the check costs a fraction of
/// a global search. What it finds is verified and ranked beside the answer: a better place wins,
/// an equal one splits the confidence ("not localized" rather than a confident wrong pose).
struct CrossCheckParams {
  bool enabled = true;
  /// Places scoring up to this much below the answer are still proposed (matcher score, 0..1):
  /// the answer is ICP-refined and the matcher's poses lie on its grid, so equal places may
  /// score a little apart.
  double score_margin = 0.05;
  /// Other places looked for, each at least the matcher's exclusion_m from the ranked
  /// hypotheses and from each other (each one is another branch-and-bound pass).
  int places = 1;
  /// Also check the best hypothesis of an answer that is not credible ("not localized"). The
  /// zone search looks in the classifier's zones only; when the classifier names the look-alike
  /// wing, it finds the mirror place there and the true one is never proposed. The whole-map
  /// search with the best's score as the bar finds the true place, which then outranks it.
  bool when_not_localized = true;
  /// A place the check finds may outrank the answer; that new best has not been checked itself,
  /// and its own look-alike may be the truth (a short-range scan in a room with a twin). The
  /// check is repeated on each new best, up to this many checks in all.
  int max_rounds = 3;
};

/// The outlines of the zones the models were trained on, in the manifest's order, picked by name
/// from `zones`. InputError(input, ...) naming the first manifest zone that has no outline there.
std::vector<Zone> zonesInManifestOrder(const ModelManifest& manifest, const std::vector<Zone>& zones,
                                       const std::string& input);

struct RelocalizerParams {
  /// The keypoint model's detections are used for this many of the classifier's most likely
  /// zones: symmetric buildings make the top zone wrong often enough that verification against
  /// the map, not the classifier, should decide between look-alikes.
  int top_zones = 2;
  /// Models trained on wall-aligned submaps see four turns of each scan; the keypoint model runs
  /// on this many of them, those whose most likely zone the classifier is surest of. The turn
  /// the classifier prefers is not always the right one, and verification decides. One turn
  /// lost 2 of the warehouse's 42 successful trials for 7.5 ms less (docs/results.md, "One
  /// keypoint turn instead of two").
  int top_turns = 2;
  /// With the cross-check on, the turns are tried in that order, and the next one only while no
  /// turn so far gave a credible ("localized") answer: the keypoint model is the costliest stage,
  /// and the cross-check then searches the map for a look-alike of that answer. Without the
  /// cross-check every top turn runs, since another turn's poses are the only check a wrong
  /// credible answer gets (stopping there made the keypoints-only relocalizer localized but
  /// wrong on 2 % of the office's first scans instead of 0 %). false: every top turn runs.
  bool stop_turns_once_localized = true;
  int max_detections_per_zone = 3;  ///< highest-scoring detections kept per zone
  /// Lower than ultralytics' prediction default (0.25): a weak detection only proposes a pose,
  /// which verification then accepts or rejects.
  PoseDecodeParams decode{0.1f, 0.7f, 300};
  KeypointHypothesesParams keypoints;
  PoseVerifierParams verifier;
  ZoneSearchParams zone_search;
  CrossCheckParams cross_check;
  CorrelativeMatcherParams matcher;  ///< for the zone search and the cross-check
  /// The zone search and the cross-check try only headings within this of the four that line the
  /// scan's walls up with the map's (MatchRequest::wall_heading_window_deg), when both have a
  /// clear wall direction [deg]. 0: every heading. On 250 simulated first scans the true heading
  /// lay within 2.3 deg of a window's centre (reports/matcher_speed, clutter and the 3.5 m lidar
  /// included), so 3 keeps a margin over that and over half the matcher's 1 deg step. 5 deg
  /// windows cut the scan to prior 1.4-3.9x against every heading; 3 deg ones cut the warehouse's
  /// by another fifth, with every outcome of 560 trials over six worlds and lidars as with 5 but
  /// one, which the scans cannot decide (docs/results.md, "Narrower heading windows"). The real
  /// maps tried have no clear wall direction and keep every heading.
  double wall_heading_window_deg = 3.0;
  OnnxRuntimeParams onnx;
  /// A scan whose field of view differs from the manifest's lidar by more than this is refused:
  /// the models never saw such submaps [deg].
  double lidar_fov_tolerance_deg = 10.0;
  /// The same for the maximum range, as a fraction of the manifest's.
  double lidar_range_tolerance = 0.25;
  TrainingMapCheckParams training_map;  ///< when a map is refused as not the one trained on
};

struct RelocalizationResult {
  Ranking ranking;                       ///< the hypotheses, best first, and whether localized
  std::vector<float> zone_probabilities;  ///< manifest zone order, of the turn the classifier was surest of
  int turns = 1;                          ///< submap turns the classifier saw (4 for wall-aligned models)
  int keypoint_turns = 0;                 ///< turns the keypoint model ran on
  int detections = 0;                     ///< keypoint-model detections used
  int candidates = 0;                     ///< poses proposed by the alignment
  bool zone_search_used = false;          ///< the keypoints gave no credible pose and the zone search ran
  int zone_search_candidates = 0;         ///< poses it proposed
  bool cross_check_used = false;          ///< the best answer was cross-checked for look-alike places
  int cross_check_candidates = 0;         ///< other places the cross-check proposed, all rounds
  int cross_check_rounds = 0;             ///< checks run: more than one when a check changed the best
  RelocalizationTimes times;
};

/// One scan -> submap (one heading-up, or four wall-aligned turns) -> zone probabilities ->
/// keypoints on the top zones of the top turns -> robust SE(2) alignment to the zones' landmarks
/// -> ICP and scan-fit verification against the map; when that leaves nothing credible and the
/// zones' outlines are known, a correlative search of the most likely zones (ZoneSearchParams);
/// when it gives a credible answer, a check of the map for look-alikes (CrossCheckParams).
class Relocalizer {
 public:
  /// Loads `<models_dir>/manifest.json` and both models. InputError when the models or the
  /// manifest cannot be used, or do not fit `map`: another cell size than the map trained on, or
  /// landmarks outside it. The zone search reads the zones the models were trained on from the
  /// folder when the manifest names them (krp-train-map copies them there); without them there
  /// is no zone search.
  Relocalizer(const std::string& models_dir, const mrpt::maps::COccupancyGridMap2D& map, RelocalizerParams params = {});
  /// The same, with the outlines of the zones the models were trained on (zones.yaml), used
  /// instead of the folder's. InputError("zones", ...) when a manifest zone has no outline there.
  Relocalizer(const std::string& models_dir, const mrpt::maps::COccupancyGridMap2D& map, RelocalizerParams params,
              const std::vector<Zone>& zones);

  /// InputError("scan", ...) for a scan from a lidar the models were not trained for (field of
  /// view or range outside the tolerances of RelocalizerParams).
  RelocalizationResult relocalize(const mrpt::obs::CObservation2DRangeScan& scan) const;

  const ModelManifest& manifest() const { return manifest_; }
  const PoseVerifier& verifier() const { return verifier_; }
  bool hasZoneSearch() const { return !zone_regions_.empty(); }
  /// Why the zone search is off although the parameters ask for it: the manifest names no zone
  /// outlines (models trained before krp-train-map wrote them beside the models) and none were
  /// given. Empty when the zone search is on, or asked off. For a warning: without it a scan
  /// whose keypoints give no credible pose gets no hypothesis, where krp-bench's `seeded`, which
  /// passes each world's zones, would have searched the classifier's zone.
  std::string zoneSearchMissing() const;

 private:
  /// Both public constructors: the zones given, else those the manifest names, else none; one
  /// source is read, once.
  Relocalizer(const std::string& models_dir, const mrpt::maps::COccupancyGridMap2D& map, RelocalizerParams params,
              const std::vector<Zone>* given_zones);
  void requireTrainingLidar(const mrpt::obs::CObservation2DRangeScan& scan) const;
  void enableZoneSearch(const mrpt::maps::COccupancyGridMap2D& map, const std::vector<Zone>& zones);
  std::vector<PoseHypothesis> zoneSearch(const mrpt::obs::CObservation2DRangeScan& scan,
                                         const std::vector<float>& zone_probabilities) const;
  std::vector<PoseHypothesis> crossCheck(const mrpt::obs::CObservation2DRangeScan& scan, const Ranking& ranking) const;

  RelocalizerParams params_;
  ModelManifest manifest_;
  ZoneClassifier classifier_;
  KeypointDetector detector_;
  PoseVerifier verifier_;
  std::optional<CorrelativeMatcher> matcher_;  ///< when the zone search or the cross-check may run
  std::vector<cv::Mat> zone_regions_;  ///< the matcher's search region of each zone, manifest order
};

}  // namespace krp
