// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/thesis_comparison.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/progress_bar.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/common/statistics.h"
#include "mrpt_krp_plugin/dataset/zone_pose_sampler.h"
#include "mrpt_krp_plugin/inference/model_manifest.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "mrpt_krp_plugin/relocalize/icp_refiner.h"
#include "mrpt_krp_plugin/relocalize/relocalizer.h"
#include "mrpt_krp_plugin/sim/clutter.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/submap/occupancy_image.h"
#include "mrpt_krp_plugin/submap/submap_builder.h"
#include "mrpt_krp_plugin/zones/zones_yaml.h"

namespace krp {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
/// Seed streams: the reference database and the held-out samples never share a draw.
constexpr uint64_t kReferenceStream = 1;
constexpr uint64_t kTestStream = 2;

mrpt::math::TPoint2D areaCentroid(const std::vector<mrpt::math::TPoint2D>& polygon) {
  double area2 = 0, cx = 0, cy = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const auto& a = polygon[i];
    const auto& b = polygon[(i + 1) % polygon.size()];
    const double cross = a.x * b.y - b.x * a.y;
    area2 += cross;
    cx += (a.x + b.x) * cross;
    cy += (a.y + b.y) * cross;
  }
  return {cx / (3.0 * area2), cy / (3.0 * area2)};
}

/// The relocalizer reduced to the thesis's keypoint stage: no zone search, no cross-check.
RelocalizerParams keypointStageParams(bool icp) {
  RelocalizerParams p;
  p.zone_search.zones = 0;
  p.cross_check.enabled = false;
  p.verifier.icp_refine = icp;
  return p;
}

std::optional<mrpt::math::TPose2D> bestPose(const RelocalizationResult& r) {
  if (r.ranking.hypotheses.empty()) return std::nullopt;
  return r.ranking.hypotheses.front().pose;
}

}  // namespace

AlignmentScores scoreAlignment(const std::string& method, const std::vector<mrpt::math::TPose2D>& truth,
                               const std::vector<std::optional<mrpt::math::TPose2D>>& estimate,
                               double right_within_m, double right_within_deg) {
  AlignmentScores s;
  s.method = method;
  s.samples = static_cast<int>(truth.size());
  std::vector<double> distances;
  double sum_d2 = 0, sum_a2 = 0;
  int right = 0;
  for (size_t i = 0; i < truth.size(); ++i) {
    if (!estimate[i]) continue;
    const double d = std::hypot(estimate[i]->x - truth[i].x, estimate[i]->y - truth[i].y);
    const double a = std::abs(mrpt::math::wrapToPi(estimate[i]->phi - truth[i].phi)) * kRadToDeg;
    distances.push_back(d);
    sum_d2 += d * d;
    sum_a2 += a * a;
    right += d <= right_within_m && a <= right_within_deg;
  }
  s.answered = static_cast<int>(distances.size());
  if (s.answered > 0) {
    s.rmse_m = std::sqrt(sum_d2 / s.answered);
    s.rmse_deg = std::sqrt(sum_a2 / s.answered);
    s.median_m = median(distances);
  }
  s.right_share = s.samples ? double(right) / s.samples : 0.0;
  return s;
}

ThesisComparison runThesisComparison(const World& world, const std::string& lidar, const std::string& models_dir,
                                     const ThesisComparisonParams& params, std::ostream& progress) {
  if (params.references_per_zone < 1 || params.tests_per_zone < 1)
    throw InputError("thesis comparison", "needs at least one reference and one test submap per zone");
  ThesisComparison out;
  out.world = world.name;
  out.lidar = lidar;
  out.models_dir = models_dir;
  out.params = params;
  const auto map = loadOccupancyMap(world.map_path);
  const auto manifest = readModelManifest(models_dir);
  out.zone_names = manifest.zones;
  const auto zones = zonesInManifestOrder(manifest, readZonesYaml(world.zones_path), world.zones_path);
  const ZonePoseSampler sampler(*map.grid, zones, params.clearance_m);
  const ScanSimulator simulator(world.lidar(lidar));
  SubmapParams sp;
  sp.size_m = manifest.submap_size_m;
  sp.size_px = manifest.submap_size_px;
  sp.orientation = manifest.submap_orientation;

  const Relocalizer keypoints(models_dir, *map.grid, keypointStageParams(false));
  const Relocalizer keypoints_icp(models_dir, *map.grid, keypointStageParams(true));
  IcpRefineParams icp_params;
  icp_params.max_correspondence_m = params.icp_start_correspondence_m;
  icp_params.max_shift_m = std::numeric_limits<double>::infinity();
  icp_params.max_turn_deg = 360.0;
  const IcpRefiner icp(*map.grid, icp_params);

  const int n_zones = static_cast<int>(zones.size());
  FeatureZoneClassifier sift(FeatureKind::kSift, n_zones, params.features), orb(FeatureKind::kOrb, n_zones, params.features);
  ProgressBar bar("thesis tables", static_cast<size_t>(n_zones) * (params.references_per_zone + params.tests_per_zone),
                  progress);

  // One scene: a pose in the zone, the map with its own unmapped objects, the scan there.
  auto scene = [&](uint64_t stream, int zone, int index) {
    Rng rng(deriveSeed(deriveSeed(params.seed, stream), static_cast<uint64_t>(zone) * 1000003u + index));
    const auto pose = sampler.sample(static_cast<size_t>(zone), rng);
    const auto scan = params.clutter ? simulator.simulate(addClutter(*map.grid, world.clutter, rng), pose, rng)
                                     : simulator.simulate(*map.grid, pose, rng);
    return std::make_pair(pose, scan);
  };
  auto occupancyImage = [&](const mrpt::obs::CObservation2DRangeScan& scan) {
    return renderOccupancyImage(buildSubmap(scan, sp, submapImageHeadings(scan, sp).front()).grid);
  };

  for (int z = 0; z < n_zones; ++z)
    for (int i = 0; i < params.references_per_zone; ++i) {
      const auto image = occupancyImage(*scene(kReferenceStream, z, i).second);
      sift.addReference(z, image);
      orb.addReference(z, image);
      bar.advance(1, "reference " + out.zone_names[z]);
    }

  for (int z = 0; z < n_zones; ++z) {
    const auto centre = areaCentroid(zones[z].polygon);
    for (int i = 0; i < params.tests_per_zone; ++i) {
      const auto [pose, scan] = scene(kTestStream, z, i);
      ThesisSample s;
      s.zone = z;
      s.truth = pose.asTPose();
      const auto image = occupancyImage(*scan);
      s.sift = sift.classify(image);
      s.orb = orb.classify(image);
      const auto raw = keypoints.relocalize(*scan);
      const auto& p = raw.zone_probabilities;
      s.cnn = static_cast<int>(std::max_element(p.begin(), p.end()) - p.begin());
      s.keypoints = bestPose(raw);
      s.keypoints_icp = bestPose(keypoints_icp.relocalize(*scan));
      s.icp_from_centre = icp.refine(*scan, {centre.x, centre.y, s.truth.phi});
      out.samples.push_back(s);
      bar.advance(1, "test " + out.zone_names[z]);
    }
  }
  bar.finish();

  std::vector<int> truth, cnn, sift_pred, orb_pred;
  std::vector<mrpt::math::TPose2D> poses;
  std::vector<std::optional<mrpt::math::TPose2D>> kp, kp_icp, centre_icp;
  for (const auto& s : out.samples) {
    truth.push_back(s.zone);
    cnn.push_back(s.cnn);
    sift_pred.push_back(s.sift);
    orb_pred.push_back(s.orb);
    poses.push_back(s.truth);
    kp.push_back(s.keypoints);
    kp_icp.push_back(s.keypoints_icp);
    centre_icp.push_back(s.icp_from_centre);
  }
  out.cnn = scoreClassification(truth, cnn, n_zones);
  out.sift = scoreClassification(truth, sift_pred, n_zones);
  out.orb = scoreClassification(truth, orb_pred, n_zones);
  const double m = params.right_within_m, deg = params.right_within_deg;
  out.alignment = {scoreAlignment("ICP from the zone's centre (true heading)", poses, centre_icp, m, deg),
                   scoreAlignment("YOLOv8-pose keypoint alignment", poses, kp, m, deg),
                   scoreAlignment("keypoint alignment + ICP (the relocalizer's keypoint stage)", poses, kp_icp, m, deg)};
  return out;
}

}  // namespace krp
