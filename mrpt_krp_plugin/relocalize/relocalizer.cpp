// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/relocalizer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <numeric>
#include <opencv2/core.hpp>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/relocalize/matcher_relocalizer.h"
#include "mrpt_krp_plugin/relocalize/training_map_check.h"
#include "mrpt_krp_plugin/submap/occupancy_image.h"
#include "mrpt_krp_plugin/submap/sdt_image.h"
#include "mrpt_krp_plugin/submap/submap_builder.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

namespace krp {

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

/// The `count` zone indices with the highest probability.
std::vector<int> topZones(const std::vector<float>& probs, int count) {
  std::vector<int> idx(probs.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) { return probs[a] > probs[b]; });
  idx.resize(std::min<size_t>(idx.size(), static_cast<size_t>(std::max(count, 0))));
  return idx;
}

}  // namespace

Relocalizer::Relocalizer(const std::string& models_dir, const mrpt::maps::COccupancyGridMap2D& map,
                         RelocalizerParams params)
    : Relocalizer(models_dir, map, params, nullptr) {}

Relocalizer::Relocalizer(const std::string& models_dir, const mrpt::maps::COccupancyGridMap2D& map,
                         RelocalizerParams params, const std::vector<Zone>& zones)
    : Relocalizer(models_dir, map, params, &zones) {}

Relocalizer::Relocalizer(const std::string& models_dir, const mrpt::maps::COccupancyGridMap2D& map,
                         RelocalizerParams params, const std::vector<Zone>* given_zones)
    : params_(params),
      manifest_(readModelManifest(models_dir)),
      classifier_(manifest_, params.onnx),
      detector_(manifest_, params.onnx),
      verifier_(map, params.verifier) {
  requireTrainingMap(manifest_, map, params.training_map);
  if (params_.cross_check.enabled && params_.cross_check.max_rounds < 1)
    throw InputError("cross-check max_rounds", "must be 1 or more when the cross-check is on");
  if (!MatchRequest::validWallHeadingWindow(params_.wall_heading_window_deg))
    throw InputError("wall_heading_window_deg", "must be " + MatchRequest::wallHeadingWindowRange() + ", got " +
                                                    std::to_string(params_.wall_heading_window_deg));
  if (params_.cross_check.enabled) matcher_.emplace(map, params_.matcher);
  if (given_zones)
    enableZoneSearch(map, *given_zones);
  else if (!manifest_.zone_outlines_file.empty())
    enableZoneSearch(map, readZonesYaml(manifest_.zoneOutlinesPath()));
}

std::vector<Zone> zonesInManifestOrder(const ModelManifest& manifest, const std::vector<Zone>& zones,
                                       const std::string& input) {
  std::vector<Zone> ordered;
  for (const auto& name : manifest.zones) {
    const auto it = std::find_if(zones.begin(), zones.end(), [&](const Zone& z) { return z.name == name; });
    if (it == zones.end())
      throw InputError(input, "no zone named '" + name + "', which the models in " + manifest.folder +
                                  " were trained on: give the zones.yaml of their world '" + manifest.world + "'");
    ordered.push_back(*it);
  }
  return ordered;
}

void Relocalizer::enableZoneSearch(const mrpt::maps::COccupancyGridMap2D& map, const std::vector<Zone>& zones) {
  zone_regions_.clear();
  if (params_.zone_search.zones <= 0) return;
  if (!matcher_) matcher_.emplace(map, params_.matcher);
  for (const auto& zone : zonesInManifestOrder(manifest_, zones, "zones")) zone_regions_.push_back(matcher_->regionOf({zone}));
}

std::string Relocalizer::zoneSearchMissing() const {
  if (hasZoneSearch() || params_.zone_search.zones <= 0) return "";
  return "the models in " + manifest_.folder +
         " name no zone outlines and none were given, so the zone search is off: a scan whose keypoints give no "
         "credible pose gets no hypothesis. Give the zones.yaml of world '" +
         manifest_.world + "' that the models were trained on";
}

std::vector<PoseHypothesis> Relocalizer::zoneSearch(const mrpt::obs::CObservation2DRangeScan& scan,
                                                    const std::vector<float>& zone_probabilities) const {
  std::vector<PoseHypothesis> found;
  const auto zones = topZones(zone_probabilities, params_.zone_search.zones);
  if (zones.empty()) return found;
  cv::Mat region = zone_regions_[zones.front()].clone();
  for (size_t i = 1; i < zones.size(); ++i) cv::bitwise_or(region, zone_regions_[zones[i]], region);
  MatchRequest request = MatchRequest::within(region);
  request.wall_heading_window_deg = params_.wall_heading_window_deg;
  for (const auto& s : matcher_->match(scan, request)) {
    PoseHypothesis h = hypothesisFromMatch(s, params_.matcher);
    h.zone = zones.front();
    h.zone_probability = zone_probabilities[zones.front()];
    found.push_back(h);
  }
  return found;
}

std::vector<PoseHypothesis> Relocalizer::crossCheck(const mrpt::obs::CObservation2DRangeScan& scan,
                                                    const Ranking& ranking) const {
  const double bar = matcher_->scoreAt(scan, ranking.hypotheses.front().pose) - params_.cross_check.score_margin;
  MatchRequest request;
  request.min_score = std::max(bar, params_.matcher.min_score);
  request.solutions = params_.cross_check.places;
  request.wall_heading_window_deg = params_.wall_heading_window_deg;
  // A place already ranked, found again, is no alternative to it.
  for (const auto& h : ranking.hypotheses) request.excluded.push_back({h.pose.x, h.pose.y});
  std::vector<PoseHypothesis> found;
  for (const auto& s : matcher_->match(scan, request))
    found.push_back(hypothesisFromMatch(s, params_.matcher));  // zone unknown: the place is what counts
  return found;
}

void Relocalizer::requireTrainingLidar(const mrpt::obs::CObservation2DRangeScan& scan) const {
  // MRPT's aperture of a 360 deg scanner leaves out one beam spacing; compare the full coverage.
  const double n = static_cast<double>(scan.getScanSize());
  const double fov_deg = n > 1 ? scan.aperture * n / (n - 1) * 180.0 / M_PI : 0.0;
  const double range_m = scan.maxRange;
  const bool fov_ok = std::abs(fov_deg - manifest_.lidar_fov_deg) <= params_.lidar_fov_tolerance_deg;
  const bool range_ok =
      std::abs(range_m - manifest_.lidar_max_range_m) <= params_.lidar_range_tolerance * manifest_.lidar_max_range_m;
  if (fov_ok && range_ok) return;
  std::ostringstream s;
  s << "the models were trained for lidar '" << manifest_.lidar_name << "' (" << manifest_.lidar_fov_deg << " deg, "
    << manifest_.lidar_max_range_m << " m); this scan covers " << fov_deg << " deg to " << range_m
    << " m: train models for this lidar (krp-train-map --lidar)";
  throw InputError("scan", s.str());
}

RelocalizationResult Relocalizer::relocalize(const mrpt::obs::CObservation2DRangeScan& scan) const {
  requireTrainingLidar(scan);
  RelocalizationResult r;
  const auto start = Clock::now();
  auto t = start;
  SubmapParams sp;
  sp.size_m = manifest_.submap_size_m;
  sp.size_px = manifest_.submap_size_px;
  sp.orientation = manifest_.submap_orientation;
  struct Turn {
    Submap submap;
    cv::Mat occupancy;
    std::vector<float> probabilities;
    float best = 0;  ///< the highest zone probability: how sure the classifier is of this turn
  };
  std::vector<Turn> turns;
  for (double heading : submapImageHeadings(scan, sp)) {
    Submap submap = buildSubmap(scan, sp, heading);
    cv::Mat occupancy = renderOccupancyImage(submap.grid);
    turns.push_back({std::move(submap), std::move(occupancy), {}, 0});
  }
  r.times.submap_ms = msSince(t);
  r.turns = static_cast<int>(turns.size());

  t = Clock::now();
  for (auto& turn : turns) {
    turn.probabilities = classifier_.probabilities(turn.occupancy);
    turn.best = *std::max_element(turn.probabilities.begin(), turn.probabilities.end());
  }
  std::stable_sort(turns.begin(), turns.end(), [](const Turn& a, const Turn& b) { return a.best > b.best; });
  turns.resize(std::min<size_t>(turns.size(), static_cast<size_t>(std::max(params_.top_turns, 1))));
  r.zone_probabilities = turns.front().probabilities;
  r.times.classifier_ms = msSince(t);

  // Each turn's poses are scored once, as they come; the ranking is over all turns tried.
  std::vector<PoseHypothesis> scored;
  const bool stop_once_localized = params_.stop_turns_once_localized && params_.cross_check.enabled;
  for (const auto& turn : turns) {
    if (stop_once_localized && r.ranking.localized) break;
    t = Clock::now();
    const cv::Mat sdt = renderSdtImage(turn.submap.grid, SdtImageParams{manifest_.sdt_clip_m});
    r.times.submap_ms += msSince(t);
    t = Clock::now();
    const auto all = detector_.detect(sdt, params_.decode);  // best score first
    r.times.keypoints_ms += msSince(t);

    t = Clock::now();
    std::vector<PoseDetection> used;
    for (int zone : topZones(turn.probabilities, params_.top_zones)) {
      int kept = 0;
      for (const auto& d : all)
        if (d.class_id == zone && kept < params_.max_detections_per_zone) used.push_back(d), ++kept;
    }
    r.detections += static_cast<int>(used.size());
    auto found = keypointHypotheses(used, turn.submap.grid, manifest_.landmarks, turn.probabilities, params_.keypoints);
    r.candidates += static_cast<int>(found.size());
    r.times.alignment_ms += msSince(t);

    t = Clock::now();
    auto verified = verifier_.refineAndScore(scan, std::move(found));
    scored.insert(scored.end(), std::make_move_iterator(verified.begin()), std::make_move_iterator(verified.end()));
    r.ranking = verifier_.rank(scored);
    r.times.verification_ms += msSince(t);
    ++r.keypoint_turns;
  }

  if (!r.ranking.localized && hasZoneSearch()) {
    t = Clock::now();
    auto found = verifier_.refineAndScore(scan, zoneSearch(scan, r.zone_probabilities));
    r.zone_search_used = true;
    r.zone_search_candidates = static_cast<int>(found.size());
    scored.insert(scored.end(), found.begin(), found.end());
    r.ranking = verifier_.rank(scored);
    r.times.zone_search_ms = msSince(t);
  }
  const bool check = params_.cross_check.enabled && !r.ranking.hypotheses.empty() &&
                     (r.ranking.localized || params_.cross_check.when_not_localized);
  if (check) {
    t = Clock::now();
    r.cross_check_used = true;
    for (int round = 0; round < params_.cross_check.max_rounds; ++round) {
      const auto checked = r.ranking.hypotheses.front().pose;
      auto found = verifier_.refineAndScore(scan, crossCheck(scan, r.ranking));
      ++r.cross_check_rounds;
      r.cross_check_candidates += static_cast<int>(found.size());
      scored.insert(scored.end(), found.begin(), found.end());
      r.ranking = verifier_.rank(scored);
      if (found.empty() || r.ranking.hypotheses.empty() || samePlace(r.ranking.hypotheses.front().pose, checked, params_.verifier.ranking))
        break;
    }
    r.times.cross_check_ms = msSince(t);
  }
  r.times.total_ms = msSince(start);
  return r;
}

}  // namespace krp
