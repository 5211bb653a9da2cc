// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include <string>
#include <vector>

namespace krp {

/// The thesis's classical baseline for zoning (its Table 4.4): local image features of the
/// submap's occupancy image matched against a reference database of each zone.
enum class FeatureKind { kSift, kOrb };

std::string featureKindName(FeatureKind kind);

struct FeatureZoneClassifierParams {
  int max_features = 500;  ///< keypoints kept per image (strongest first)
  /// Lowe's ratio test: a match counts when its distance is below this share of the second
  /// best's, the usual rejection of ambiguous matches.
  double ratio = 0.75;
};

/// Reference images are added per zone; a query goes to the zone whose pooled descriptors give it
/// the most matches that pass the ratio test (-1 when no zone gives any). SIFT descriptors are
/// compared with the L2 norm, ORB's with the Hamming norm.
class FeatureZoneClassifier {
 public:
  FeatureZoneClassifier(FeatureKind kind, int zones, FeatureZoneClassifierParams params = {});

  void addReference(int zone, const cv::Mat& image);
  /// Good matches per zone for `image`.
  std::vector<int> goodMatches(const cv::Mat& image) const;
  /// The zone with the most good matches; -1 when none has any (ties go to the lower index).
  int classify(const cv::Mat& image) const;

 private:
  cv::Mat describe(const cv::Mat& image) const;

  FeatureKind kind_;
  FeatureZoneClassifierParams params_;
  cv::Ptr<cv::Feature2D> features_;
  std::vector<cv::Mat> zone_descriptors_;  ///< per zone: every reference's descriptors, stacked
};

}  // namespace krp
