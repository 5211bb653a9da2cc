// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include "mrpt_krp_plugin/bench/method_registry.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/filter/amcl_kld_initializer.h"
#include "mrpt_krp_plugin/filter/uniform_initializer.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "support/test_maps.h"

namespace krp {
namespace {

TEST(AmclKld, ZMapsToMrptDeltaThroughTheNormalCdf) {
  AmclKldParams p;
  p.kld_z = 0.0;
  EXPECT_NEAR(p.mrptKldDelta(), 0.5, 1e-12);
  p.kld_z = 0.99;  // amcl's default
  EXPECT_NEAR(p.mrptKldDelta(), 1.0 - 0.838913, 1e-5);
  p.kld_z = 2.326;
  EXPECT_NEAR(p.mrptKldDelta(), 0.01, 1e-4);
}

TEST(AmclKld, InitializerSetsAmclDefaults) {
  const auto room = test::asymmetricRoom();
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  AmclKldInitializer init;
  init.initialize(pf, o, room, mrpt::obs::CSensoryFrame());
  EXPECT_TRUE(o.adaptiveSampleSize);
  EXPECT_EQ(pf.size(), 5000u);
  EXPECT_EQ(pf.options.KLD_params.KLD_maxSampleSize, 5000u);
  EXPECT_EQ(pf.options.KLD_params.KLD_minSampleSize, 100u);
  EXPECT_NEAR(pf.options.KLD_params.KLD_binSize_XY, 0.5, 1e-12);
  EXPECT_NEAR(pf.options.KLD_params.KLD_epsilon, 0.01, 1e-12);
}

TEST(Uniform, SizesByFreeAreaWithinBounds) {
  const auto room = test::asymmetricRoom();  // ~45 m^2 free
  UniformInitParams p;
  p.particles_per_m2 = 100.0;
  p.min_particles = 10;
  UniformInitializer init(p);
  const auto n = init.particleCount(room);
  EXPECT_NEAR(static_cast<double>(n), 100.0 * freeAreaM2(room), 1.0);
  mrpt::slam::CMonteCarloLocalization2D pf;
  mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
  init.initialize(pf, o, room, mrpt::obs::CSensoryFrame());
  EXPECT_EQ(pf.size(), n);
  EXPECT_FALSE(o.adaptiveSampleSize);
  // MRPT 2.5.8 jitters each particle around its free cell's centre by up to a whole cell,
  // so particles next to a wall can land inside it; the large majority must be free.
  size_t on_free = 0;
  for (const auto& part : pf.m_particles) on_free += room.getPos(part.d.x, part.d.y) > 0.6 ? 1 : 0;
  EXPECT_GT(static_cast<double>(on_free) / static_cast<double>(pf.size()), 0.9);
}

TEST(MethodRegistry, KnowsItsMethodsAndRejectsOthers) {
  MethodSettings s;
  for (const auto& name : methodNames()) {
    if (methodNeedsModels(name) || methodNeedsMatcher(name))
      EXPECT_THROW(makeInitializer(name, s), InputError) << name << " without models";
    else
      EXPECT_EQ(makeInitializer(name, s)->name(), name);
  }
  EXPECT_THROW(makeInitializer("magic", s), InputError);
}

}  // namespace
}  // namespace krp
