// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/single_scan_sweep.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/png_file.h"
#include "mrpt_krp_plugin/common/progress_bar.h"
#include "mrpt_krp_plugin/common/statistics.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
constexpr double kP95 = 0.95;
// Drawing: dots this large stand for one scan, whatever the map's resolution [m].
constexpr double kDotRadiusM = 0.25;

}  // namespace

std::vector<SingleScanRecord> sweepSingleScans(const HypothesisSource& source, const std::vector<RawlogStep>& steps,
                                               const std::vector<mrpt::math::TPose2D>& truth, std::size_t stride,
                                               const ConvergenceCriteria& right, std::ostream* progress) {
  if (stride == 0) throw InputError("stride", "must be at least 1");
  if (!truth.empty() && truth.size() != steps.size())
    throw InputError("ground truth", std::to_string(truth.size()) + " poses for " + std::to_string(steps.size()) + " scans");
  std::optional<ProgressBar> bar;
  if (progress) bar.emplace("single-scan relocalization", (steps.size() + stride - 1) / stride, *progress);
  std::vector<SingleScanRecord> out;
  for (std::size_t i = 0; i < steps.size(); i += stride) {
    SingleScanRecord r;
    r.step = i;
    const auto scan = steps[i].observations ? steps[i].observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>()
                                            : nullptr;
    if (!scan) throw InputError("step " + std::to_string(i), "holds no 2D range scan");
    const auto start = std::chrono::steady_clock::now();
    const Ranking ranking = source(*scan);
    r.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    r.localized = ranking.localized;
    r.reason = ranking.reason;
    r.hypotheses = ranking.hypotheses.size();
    if (!ranking.hypotheses.empty()) {
      const auto& h = ranking.hypotheses.front();
      r.best = h.pose;
      r.confidence = h.confidence;
      r.fit_fraction = h.fit_fraction;
      r.best_from_keypoints = h.origin == PoseOrigin::kKeypoints;
      if (!truth.empty()) {
        r.error_xy_m = std::hypot(h.pose.x - truth[i].x, h.pose.y - truth[i].y);
        r.error_phi_deg = std::abs(mrpt::math::wrapToPi(h.pose.phi - truth[i].phi)) * kRadToDeg;
        r.best_right = withinTolerance(r.error_xy_m, r.error_phi_deg, right);
      }
    }
    out.push_back(r);
    if (bar) bar->advance(1, r.localized ? "localized" : "not localized");
  }
  if (bar) bar->finish();
  return out;
}

SingleScanSummary summarizeSweep(const std::vector<SingleScanRecord>& records) {
  SingleScanSummary s;
  std::vector<double> times, errors_xy, errors_phi;
  for (const auto& r : records) {
    ++s.scans;
    times.push_back(r.time_ms);
    s.has_truth = s.has_truth || r.error_xy_m >= 0;
    s.best_right += r.best_right ? 1 : 0;
    if (!r.localized) continue;
    ++s.localized;
    s.localized_from_keypoints += r.best_from_keypoints ? 1 : 0;
    (r.best_right ? s.localized_right : s.localized_wrong) += 1;
    if (r.error_xy_m >= 0) errors_xy.push_back(r.error_xy_m), errors_phi.push_back(r.error_phi_deg);
  }
  if (!errors_xy.empty()) {
    s.median_error_xy_m = median(errors_xy);
    s.median_error_phi_deg = median(errors_phi);
  }
  if (!times.empty()) {
    s.median_ms = median(times);
    s.p95_ms = quantile(times, kP95);
  }
  return s;
}

std::string sweepCsv(const std::vector<SingleScanRecord>& records) {
  std::ostringstream o;
  o.precision(6);
  o << "step,localized,hypotheses,best_x_m,best_y_m,best_yaw_deg,confidence,fit_fraction,time_ms,error_xy_m,error_phi_deg,"
       "best_right,best_from,reason\n";
  for (const auto& r : records) {
    o << r.step << "," << r.localized << "," << r.hypotheses << ",";
    if (r.best)
      o << r.best->x << "," << r.best->y << "," << r.best->phi * kRadToDeg;
    else
      o << ",,";
    std::string reason = r.reason;
    std::replace(reason.begin(), reason.end(), ',', ';');
    o << "," << r.confidence << "," << r.fit_fraction << "," << r.time_ms << "," << r.error_xy_m << "," << r.error_phi_deg
      << "," << r.best_right << "," << (!r.best ? "" : r.best_from_keypoints ? "keypoints" : "matcher") << "," << reason
      << "\n";
  }
  return o.str();
}

std::string sweepSummaryText(const SingleScanSummary& s) {
  auto pct = [&](std::size_t n) {
    std::ostringstream o;
    o.precision(3);
    o << n << " (" << (s.scans ? 100.0 * static_cast<double>(n) / static_cast<double>(s.scans) : 0.0) << " %)";
    return o.str();
  };
  std::ostringstream o;
  o << "scans relocalized: " << s.scans << "\nsaid localized: " << pct(s.localized) << "\n";
  if (s.has_truth)
    o << "localized and right: " << pct(s.localized_right) << "\nlocalized but wrong: " << pct(s.localized_wrong)
      << "\nbest hypothesis right (any verdict): " << pct(s.best_right) << "\nmedian error when localized: "
      << s.median_error_xy_m << " m, " << s.median_error_phi_deg << " deg\n";
  else
    o << "no ground truth: right and wrong not counted\n";
  o << "localized from the keypoint model: " << pct(s.localized_from_keypoints) << "\n";
  o << "time per scan: median " << s.median_ms << " ms, p95 " << s.p95_ms << " ms\n";
  return o.str();
}

void writeSweepPng(const mrpt::maps::COccupancyGridMap2D& map, const std::vector<SingleScanRecord>& records,
                   const std::vector<mrpt::math::TPose2D>& truth, const std::string& png_path) {
  cv::Mat img;
  cv::cvtColor(gridToGrey(map), img, cv::COLOR_GRAY2BGR);
  const cv::Scalar path_colour(220, 80, 0), right(40, 170, 40), wrong(0, 0, 230), not_localized(150, 150, 150);
  const int thickness = std::max(1, img.cols / 800);
  for (std::size_t i = 1; i < truth.size(); ++i)
    cv::line(img, worldToPixel(map, {truth[i - 1].x, truth[i - 1].y}), worldToPixel(map, {truth[i].x, truth[i].y}),
             path_colour, thickness, cv::LINE_AA);
  const int radius = std::max(2, static_cast<int>(kDotRadiusM / map.getResolution()));
  for (const auto& r : records) {
    const bool has_truth = r.step < truth.size();
    if (!has_truth && !r.best) continue;
    const auto at = has_truth ? truth[r.step] : *r.best;
    const cv::Scalar colour = !r.localized ? not_localized : (!has_truth || r.best_right ? right : wrong);
    cv::circle(img, worldToPixel(map, {at.x, at.y}), radius, colour, cv::FILLED, cv::LINE_AA);
  }
  writePngAtomically(png_path, img);
}

}  // namespace krp
