// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/feature_zone_classifier.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace krp {
namespace {

// Two "zones" with different drawings: a zone's own drawing, shifted a little, matches it best.
cv::Mat drawing(int zone, int shift) {
  cv::Mat image(160, 160, CV_8UC1, cv::Scalar(127));
  cv::RNG rng(zone == 0 ? 11 : 29);
  for (int i = 0; i < 14; ++i) {
    const cv::Point a(rng.uniform(5, 150) + shift, rng.uniform(5, 150));
    const cv::Point b(a.x + rng.uniform(8, 30), a.y + rng.uniform(8, 30));
    cv::rectangle(image, a, b, cv::Scalar(rng.uniform(0, 2) ? 0 : 255), cv::FILLED);
  }
  return image;
}

TEST(FeatureZoneClassifier, EachZoneMatchesItsOwnPlace) {
  for (auto kind : {FeatureKind::kSift, FeatureKind::kOrb}) {
    FeatureZoneClassifier c(kind, 2);
    for (int zone : {0, 1}) c.addReference(zone, drawing(zone, 0));
    for (int zone : {0, 1}) {
      const auto good = c.goodMatches(drawing(zone, 3));
      EXPECT_GT(good[zone], good[1 - zone]) << featureKindName(kind) << " zone " << zone;
      EXPECT_EQ(c.classify(drawing(zone, 3)), zone) << featureKindName(kind);
    }
  }
}

TEST(FeatureZoneClassifier, AFeaturelessImageGetsNoAnswer) {
  FeatureZoneClassifier c(FeatureKind::kOrb, 2);
  for (int zone : {0, 1}) c.addReference(zone, drawing(zone, 0));
  EXPECT_EQ(c.classify(cv::Mat(160, 160, CV_8UC1, cv::Scalar(127))), -1);
  EXPECT_THROW(c.addReference(2, drawing(0, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace krp
