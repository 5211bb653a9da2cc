// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/dataset/keypoint_label.h"
#include "mrpt_krp_plugin/relocalize/keypoint_hypotheses.h"
#include "mrpt_krp_plugin/relocalize/pose_verifier.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/submap/submap_builder.h"
#include "support/test_maps.h"

namespace krp {
namespace {

// asymmetricRoom()'s structural points: outer corners, the L wall's ends and bend, the block's corners.
const ZoneLandmarks kRoomLandmarks{"room", {{0.5, 0.5}, {8.5, 0.5}, {8.5, 6.5}, {0.5, 6.5}, {2.9, 2.9}, {4.1, 2.9},
                                            {6.5, 4.7}, {7.3, 5.9}}};

struct Scene {
  mrpt::maps::COccupancyGridMap2D map = test::asymmetricRoom();
  mrpt::poses::CPose2D truth{5.5, 2.0, 0.8};
  mrpt::obs::CObservation2DRangeScan::Ptr scan;
  Submap submap;

  Scene() {
    Rng rng(11);
    scan = ScanSimulator(lidarProfileByName("omni_12m")).simulate(map, truth, rng);
    SubmapParams p;
    p.size_m = 16.0;
    submap = buildSubmap(*scan, p);
  }

  /// What a perfect keypoint model would output: the landmarks the submap observed, at their
  /// projected image positions (continuous coordinates, as the decoder gives them).
  PoseDetection perfectDetection() const {
    PoseDetection d;
    d.score = 0.9f;
    for (const auto& k : projectLandmarks(kRoomLandmarks, truth, submap.grid)) {
      const float vis = k.visibility == KeypointVisibility::kObserved ? 1.0f : 0.0f;
      d.keypoints.push_back({float(k.px.x + kPixelCentreOffset), float(k.px.y + kPixelCentreOffset), vis});
    }
    return d;
  }
};

void expectNear(const mrpt::math::TPose2D& a, const mrpt::poses::CPose2D& b, double xy_m, double yaw_deg) {
  EXPECT_NEAR(a.x, b.x(), xy_m);
  EXPECT_NEAR(a.y, b.y(), xy_m);
  EXPECT_NEAR(std::abs(mrpt::math::wrapToPi(a.phi - b.phi())), 0.0, yaw_deg * M_PI / 180.0);
}

TEST(PoseVerifier, PerfectKeypointsGiveTheTruePoseThroughTheWholeGeometry) {
  // Pins every frame convention between the submap image, the robot frame and the map:
  // a mistake in any of them puts the pose metres or a right angle off.
  const Scene s;
  const auto det = s.perfectDetection();
  int observed = 0;
  for (const auto& k : det.keypoints) observed += k.visibility > 0.5f;
  ASSERT_GE(observed, 3);
  const auto candidates = keypointHypotheses({det}, s.submap.grid, {kRoomLandmarks.points}, {1.0f});
  ASSERT_EQ(candidates.size(), 1u);
  expectNear(candidates[0].pose, s.truth, 0.2, 2.0);  // pixel-quantized keypoints

  const PoseVerifier verifier(s.map);
  const auto ranking = verifier.verify(*s.scan, candidates);
  ASSERT_TRUE(ranking.localized) << ranking.reason;
  expectNear(ranking.hypotheses[0].pose, s.truth, 0.05, 1.0);
  EXPECT_GT(ranking.hypotheses[0].fit_fraction, 0.9);
  EXPECT_GT(ranking.hypotheses[0].confidence, 0.9);
}

TEST(PoseVerifier, IcpPullsAnOffsetHypothesisBackAndRejectsAWrongPlace) {
  const Scene s;
  PoseHypothesis off, wrong;
  off.pose = {s.truth.x() + 0.35, s.truth.y() - 0.25, s.truth.phi() + 0.08};
  wrong.pose = {2.0, 5.0, -2.0};
  const PoseVerifier verifier(s.map);
  const auto ranking = verifier.verify(*s.scan, {wrong, off});
  ASSERT_EQ(ranking.hypotheses.size(), 1u) << "the wrong place must not explain the scan";
  expectNear(ranking.hypotheses[0].pose, s.truth, 0.05, 1.0);

  PoseVerifierParams no_icp;
  no_icp.icp_refine = false;
  const auto unrefined = PoseVerifier(s.map, no_icp).verify(*s.scan, {off});
  EXPECT_TRUE(unrefined.hypotheses.empty() || unrefined.hypotheses[0].fit_fraction < 0.6)
      << "35 cm off, the scan cannot fit the map this well without ICP";
}

TEST(ScanFit, ExplainsTheScanOnlyAtTheTruePose) {
  const Scene s;
  const ScanFitScorer scorer(s.map);
  const auto at_truth = scorer.score(*s.scan, s.truth.asTPose());
  EXPECT_GT(at_truth.fit_fraction, 0.95);
  EXPECT_GT(at_truth.returns, 600);
  const auto turned = scorer.score(*s.scan, {s.truth.x(), s.truth.y(), s.truth.phi() + 0.5});
  EXPECT_LT(turned.fit_fraction, 0.5);
  EXPECT_GT(turned.mean_distance_m, at_truth.mean_distance_m);
}

}  // namespace
}  // namespace krp
