// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/relocalization_output.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "mrpt_krp_plugin/common/png_file.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
// Drawing: an arrow this long stands for a pose, whatever the map's resolution [m].
constexpr double kArrowLengthM = 1.0;
// Text: a matcher score to this many decimals tells most near-ties apart; hypotheses.json has
// every digit, for telling an exact tie from a near one.
constexpr int kScoreDecimals = 6;
// Text: metres, degrees and fractions to this many decimals (millimetres, thousandths).
constexpr int kTextDecimals = 3;

const char* originName(PoseOrigin o) { return o == PoseOrigin::kMatcher ? "matcher" : "keypoints"; }

std::string zoneName(int zone, const std::vector<std::string>& names) {
  return zone >= 0 && zone < static_cast<int>(names.size()) ? names[zone] : "?";
}

void drawPose(cv::Mat& img, const mrpt::maps::COccupancyGridMap2D& map, const mrpt::math::TPose2D& pose,
              const cv::Scalar& colour, double std_m) {
  const cv::Point a = worldToPixel(map, {pose.x, pose.y});
  const cv::Point b =
      worldToPixel(map, {pose.x + kArrowLengthM * std::cos(pose.phi), pose.y + kArrowLengthM * std::sin(pose.phi)});
  const int thickness = std::max(1, img.cols / 500);
  cv::arrowedLine(img, a, b, colour, thickness, cv::LINE_AA, 0, 0.3);
  if (std_m > 0) cv::circle(img, a, std::max(2, static_cast<int>(std_m / map.getResolution())), colour, thickness);
}

}  // namespace

nlohmann::json relocalizationJson(const RelocalizationResult& r, const std::vector<std::string>& zone_names) {
  nlohmann::json j;
  j["localized"] = r.ranking.localized;
  j["reason"] = r.ranking.reason;
  for (size_t z = 0; z < r.zone_probabilities.size(); ++z) j["zone_probabilities"][zoneName(int(z), zone_names)] = r.zone_probabilities[z];
  j["submap_turns"] = r.turns;
  j["keypoint_turns"] = r.keypoint_turns;
  j["detections"] = r.detections;
  j["candidates"] = r.candidates;
  j["zone_search"] = {{"used", r.zone_search_used}, {"candidates", r.zone_search_candidates}};
  j["cross_check"] = {{"used", r.cross_check_used}, {"candidates", r.cross_check_candidates}, {"rounds", r.cross_check_rounds}};
  j["hypotheses"] = nlohmann::json::array();
  for (const auto& h : r.ranking.hypotheses) {
    std::vector<double> cov;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) cov.push_back(h.cov(i, k));
    j["hypotheses"].push_back({{"x_m", h.pose.x}, {"y_m", h.pose.y}, {"yaw_deg", h.pose.phi * kRadToDeg},
                               {"covariance_x_y_yaw", cov}, {"zone", zoneName(h.zone, zone_names)},
                               {"zone_probability", h.zone_probability}, {"keypoint_inliers", h.keypoint_inliers},
                               {"alignment_rms_m", h.alignment_rms_m}, {"fit_fraction", h.fit_fraction},
                               {"confidence", h.confidence}, {"origin", originName(h.origin)},
                               // Full precision: two places whose scores are equal to the last bit tie exactly.
                               {"matcher_score", h.origin == PoseOrigin::kMatcher ? nlohmann::json(h.matcher_score)
                                                                                  : nlohmann::json(nullptr)}});
  }
  const auto& t = r.times;
  j["times_ms"] = {{"submap", t.submap_ms}, {"classifier", t.classifier_ms}, {"keypoints", t.keypoints_ms},
                   {"alignment", t.alignment_ms}, {"verification", t.verification_ms}, {"zone_search", t.zone_search_ms},
                   {"cross_check", t.cross_check_ms}, {"total", t.total_ms}};
  return j;
}

std::string relocalizationText(const RelocalizationResult& r, const std::vector<std::string>& zone_names) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(kTextDecimals);
  o << (r.ranking.localized ? "localized" : "NOT localized: " + r.ranking.reason) << "\nzones:";
  for (size_t z = 0; z < r.zone_probabilities.size(); ++z) o << " " << zoneName(int(z), zone_names) << " " << r.zone_probabilities[z];
  o << "\nkeypoint model on " << r.keypoint_turns << " of " << r.turns << " submap turn(s); " << r.detections
    << " detection(s), " << r.candidates << " aligned candidate(s), " << r.ranking.hypotheses.size()
    << " hypothesis(es) after verification, " << r.times.total_ms << " ms\n";
  if (r.zone_search_used)
    o << "zone search (the keypoints gave no credible pose): " << r.zone_search_candidates << " pose(s) from the matcher, "
      << r.times.zone_search_ms << " ms\n";
  if (r.cross_check_used)
    o << "cross-check for look-alike places: " << r.cross_check_candidates << " other place(s) fit about as well, "
      << r.cross_check_rounds << " round(s), " << r.times.cross_check_ms << " ms\n";
  for (size_t i = 0; i < r.ranking.hypotheses.size(); ++i) {
    const auto& h = r.ranking.hypotheses[i];
    o << "  #" << i + 1 << " x " << h.pose.x << " m, y " << h.pose.y << " m, yaw " << h.pose.phi * kRadToDeg
      << " deg; std " << std::sqrt(h.cov(0, 0)) << " / " << std::sqrt(h.cov(1, 1)) << " m, "
      << std::sqrt(h.cov(2, 2)) * kRadToDeg << " deg; zone " << zoneName(h.zone, zone_names) << "; fit "
      << h.fit_fraction << "; confidence " << h.confidence << "; from " << originName(h.origin);
    if (h.origin == PoseOrigin::kMatcher)
      o << " (score " << std::setprecision(kScoreDecimals) << h.matcher_score << std::setprecision(kTextDecimals) << ")";
    o << "\n";
  }
  return o.str();
}

void writeHypothesesPng(const mrpt::maps::COccupancyGridMap2D& map, const RelocalizationResult& r,
                        const std::optional<mrpt::math::TPose2D>& truth, const std::string& png_path) {
  cv::Mat img;
  cv::cvtColor(gridToGrey(map), img, cv::COLOR_GRAY2BGR);
  const cv::Scalar best(40, 170, 40), other(0, 140, 255), truth_colour(220, 80, 0);
  for (size_t i = r.ranking.hypotheses.size(); i-- > 0;) {
    const auto& h = r.ranking.hypotheses[i];
    drawPose(img, map, h.pose, i == 0 ? best : other, std::sqrt(std::max(h.cov(0, 0), h.cov(1, 1))));
  }
  if (truth) drawPose(img, map, *truth, truth_colour, 0.0);
  writePngAtomically(png_path, img);
}

}  // namespace krp
