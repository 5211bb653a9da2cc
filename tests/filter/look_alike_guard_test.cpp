// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/look_alike_guard.h"

#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cmath>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "support/test_maps.h"

namespace krp {
namespace {

// The 8 x 6 m asymmetric room: a pose and its 180 deg twin share most walls; only the L wall
// and the block tell them apart, so the twin fits the truth's scan less well.
const mrpt::math::TPose2D kTruth(5.52, 2.07, 0.8);
const mrpt::math::TPose2D kTwin(9.0 - 5.52, 7.0 - 2.07, mrpt::math::wrapToPi(0.8 + M_PI));

mrpt::obs::CObservation2DRangeScan::Ptr scanAtTruth(const mrpt::maps::COccupancyGridMap2D& room, uint64_t seed) {
  Rng rng(seed);
  return ScanSimulator(lidarProfileByName("omni_12m")).simulate(room, mrpt::poses::CPose2D(kTruth), rng);
}

double distance(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

TEST(LookAlikeGuard, FindsTheBetterPlaceOnlyFromTheWrongOne) {
  const auto room = test::asymmetricRoom();
  const LookAlikeGuard guard(std::make_shared<CorrelativeMatcher>(room));
  const auto scan = scanAtTruth(room, 1);
  const auto from_twin = guard.lookAlike(*scan, kTwin);
  ASSERT_TRUE(from_twin.has_value());
  EXPECT_LT(distance(*from_twin, kTruth), 0.2);
  EXPECT_FALSE(guard.lookAlike(*scan, kTruth).has_value()) << "the twin fits worse than the truth";
}

/// Puts every particle tightly on one pose: a filter that has converged there.
class OnePoseInitializer : public ParticleInitializer {
 public:
  explicit OnePoseInitializer(mrpt::math::TPose2D pose) : pose_(pose) {}
  std::string name() const override { return "one-pose"; }
  void initialize(mrpt::slam::CMonteCarloLocalization2D& pf, mrpt::bayes::CParticleFilter::TParticleFilterOptions& o,
                  const mrpt::maps::COccupancyGridMap2D&, const mrpt::obs::CSensoryFrame&) override {
    o.adaptiveSampleSize = false;
    Rng rng(3);
    pf.m_particles.assign(400, {});
    for (auto& p : pf.m_particles) {
      p.d = mrpt::math::TPose2D(rng.normal(pose_.x, 0.05), rng.normal(pose_.y, 0.05), rng.normal(pose_.phi, 0.02));
      p.log_w = 0.0;
    }
  }

 private:
  mrpt::math::TPose2D pose_;
};

// A filter that converged on the twin stays there without the guard (its scan fit is high
// enough); with it, the first update moves half the particles to the truth and the next
// scans settle there.
TEST(LookAlikeGuard, MovesAFilterCollapsedOnTheTwinToTheTruth) {
  const auto room = std::make_shared<mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  auto run = [&](bool guarded) {
    MclLocalizer loc(room, std::make_shared<OnePoseInitializer>(kTwin));
    if (guarded) loc.setLookAlikeGuard(std::make_shared<LookAlikeGuard>(std::make_shared<CorrelativeMatcher>(*room)));
    MclEstimate e;
    int found = 0;
    for (uint64_t i = 0; i < 6; ++i) {
      RawlogStep step;
      step.observations = mrpt::obs::CSensoryFrame::Create();
      step.observations->insert(scanAtTruth(*room, 10 + i));
      e = loc.update(step);
      found += e.look_alike_found;
    }
    return std::make_pair(e, found);
  };
  const auto [unguarded, none] = run(false);
  EXPECT_EQ(none, 0);
  EXPECT_LT(distance(unguarded.mean, kTwin), 0.5) << "without the guard the filter stays on the twin";
  const auto [guarded, found] = run(true);
  EXPECT_EQ(found, 1) << "one convergence, one check that moved particles";
  EXPECT_LT(distance(guarded.mean, kTruth), 0.2);
  EXPECT_LT(std::sqrt(guarded.cov(0, 0)), 0.5) << "and it converged there";
}

}  // namespace
}  // namespace krp
