// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include "mrpt_krp_plugin/filter/kidnap_detector.h"

namespace krp {
namespace {

TEST(KidnapDetector, NeedsASustainedDropAfterTheGracePeriod) {
  KidnapDetectorParams p;
  p.enabled = true;
  p.grace_updates = 2;
  p.consecutive_updates = 3;
  KidnapDetector d(p);
  EXPECT_FALSE(d.update(0.0));  // grace: the filter is still settling
  EXPECT_FALSE(d.update(0.0));
  EXPECT_FALSE(d.update(0.1));
  EXPECT_FALSE(d.update(0.1));
  EXPECT_FALSE(d.update(0.9));  // one good scan clears the count
  EXPECT_FALSE(d.update(0.1));
  EXPECT_FALSE(d.update(0.1));
  EXPECT_TRUE(d.update(0.1));
  EXPECT_FALSE(d.update(0.1));  // reset, grace again
}

TEST(KidnapDetector, DisabledNeverFires) {
  KidnapDetector d;
  for (int i = 0; i < 20; ++i) EXPECT_FALSE(d.update(0.0));
}

}  // namespace
}  // namespace krp
