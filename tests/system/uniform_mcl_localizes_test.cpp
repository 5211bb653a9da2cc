// SPDX-License-Identifier: BSD-3-Clause
// System test: uniform MCL, started with no pose knowledge, localizes a robot in an easy
// asymmetric room. Tolerances: 0.5 m / 10 deg; 5 seeded trials, at least 4 must converge.
#include <gtest/gtest.h>

#include "mrpt_krp_plugin/bench/trial_metrics.h"
#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/filter/uniform_initializer.h"
#include "mrpt_krp_plugin/sim/rawlog_io.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "support/test_maps.h"

namespace krp {
namespace {

TEST(SystemUniformMcl, LocalizesInAnEasyRoom) {
  const auto room = std::make_shared<const mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  TrialParams tp;
  tp.steps = 15;
  tp.clutter.boxes_per_100m2 = 0;
  tp.clutter.people_per_100m2 = 0;
  tp.clutter.pallets_per_100m2 = 0;
  UniformInitParams up;
  up.particles = 20000;
  int converged = 0;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const Trial t = generateTrial(*room, lidarProfileByName("omni_12m"), tp, seed);
    const auto steps = trialToSteps(t);
    MclParams mp;
    mp.seed = static_cast<uint32_t>(seed);
    MclLocalizer loc(room, std::make_shared<UniformInitializer>(up), mp);
    std::vector<UpdateRecord> u;
    for (size_t i = 0; i < steps.size(); ++i) u.push_back(makeUpdateRecord(loc.update(steps[i]), t.truth[i], t.distance_m[i]));
    const auto o = evaluateTrial(u, {});
    converged += o.converged ? 1 : 0;
    if (o.converged) {
      EXPECT_LT(o.final_error_xy_m, 0.2) << "seed " << seed;
    }
  }
  EXPECT_GE(converged, 4);
}

TEST(SystemUniformMcl, SameSeedSameResult) {
  const auto room = std::make_shared<const mrpt::maps::COccupancyGridMap2D>(test::asymmetricRoom());
  TrialParams tp;
  tp.steps = 3;
  const Trial t = generateTrial(*room, lidarProfileByName("lds01"), tp, 21);
  const auto steps = trialToSteps(t);
  UniformInitParams up;
  up.particles = 3000;
  auto run = [&]() {
    MclLocalizer loc(room, std::make_shared<UniformInitializer>(up), MclParams{});
    MclEstimate e;
    for (const auto& s : steps) e = loc.update(s);
    return e.mean;
  };
  const auto a = run();
  const auto b = run();
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.phi, b.phi);
}

}  // namespace
}  // namespace krp
