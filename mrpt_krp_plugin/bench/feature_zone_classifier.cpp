// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/feature_zone_classifier.h"

#include <algorithm>
#include <stdexcept>

namespace krp {

std::string featureKindName(FeatureKind kind) { return kind == FeatureKind::kSift ? "SIFT" : "ORB"; }

FeatureZoneClassifier::FeatureZoneClassifier(FeatureKind kind, int zones, FeatureZoneClassifierParams params)
    : kind_(kind), params_(params), zone_descriptors_(static_cast<size_t>(std::max(zones, 0))) {
  if (zones <= 0) throw std::invalid_argument("FeatureZoneClassifier: no zones");
  if (kind == FeatureKind::kSift)
    features_ = cv::SIFT::create(params.max_features);
  else
    features_ = cv::ORB::create(params.max_features);
}

cv::Mat FeatureZoneClassifier::describe(const cv::Mat& image) const {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  features_->detectAndCompute(image, cv::noArray(), keypoints, descriptors);
  return descriptors;
}

void FeatureZoneClassifier::addReference(int zone, const cv::Mat& image) {
  if (zone < 0 || zone >= static_cast<int>(zone_descriptors_.size()))
    throw std::invalid_argument("FeatureZoneClassifier: zone index out of range");
  const cv::Mat d = describe(image);
  if (d.empty()) return;
  auto& pool = zone_descriptors_[static_cast<size_t>(zone)];
  if (pool.empty())
    pool = d.clone();
  else
    cv::vconcat(pool, d, pool);
}

std::vector<int> FeatureZoneClassifier::goodMatches(const cv::Mat& image) const {
  std::vector<int> good(zone_descriptors_.size(), 0);
  const cv::Mat query = describe(image);
  if (query.empty()) return good;
  const cv::BFMatcher matcher(kind_ == FeatureKind::kSift ? cv::NORM_L2 : cv::NORM_HAMMING);
  for (size_t z = 0; z < zone_descriptors_.size(); ++z) {
    if (zone_descriptors_[z].rows < 2) continue;  // the ratio test needs a second best
    std::vector<std::vector<cv::DMatch>> pairs;
    matcher.knnMatch(query, zone_descriptors_[z], pairs, 2);
    for (const auto& p : pairs)
      if (p.size() == 2 && p[0].distance < params_.ratio * p[1].distance) ++good[z];
  }
  return good;
}

int FeatureZoneClassifier::classify(const cv::Mat& image) const {
  const auto good = goodMatches(image);
  const auto best = std::max_element(good.begin(), good.end());
  return *best > 0 ? static_cast<int>(best - good.begin()) : -1;
}

}  // namespace krp
