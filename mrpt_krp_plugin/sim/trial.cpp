// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/sim/trial.h"

#include <algorithm>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {
namespace {

// Clearance lookup on the simulation map (clutter included).
class ClearanceMap {
 public:
  explicit ClearanceMap(const mrpt::maps::COccupancyGridMap2D& g) : grid_(g), dist_(freeClearanceM(g)) {}
  double at(double x, double y) const {
    const cv::Point px = worldToPixel(grid_, {x, y});
    if (px.x < 0 || px.y < 0 || px.x >= dist_.cols || px.y >= dist_.rows) return 0.0;
    return dist_.at<float>(px);
  }
  bool segmentClear(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b, double clearance) const {
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const int n = std::max(1, static_cast<int>(std::ceil(len / grid_.getResolution())));
    for (int i = 0; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      if (at(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)) < clearance) return false;
    }
    return true;
  }
  const cv::Mat& dist() const { return dist_; }

 private:
  const mrpt::maps::COccupancyGridMap2D& grid_;
  cv::Mat dist_;
};

mrpt::poses::CPose2D noisyOdometry(const mrpt::poses::CPose2D& truth, const OdometryNoiseParams& n, Rng& rng) {
  const double d = std::hypot(truth.x(), truth.y()), dphi = std::abs(truth.phi());
  const double xy_std = n.xy_std_per_m * d;
  const double phi_std = n.phi_std_per_rad * dphi + n.phi_std_per_m * d;
  return {truth.x() + rng.normal(0, xy_std), truth.y() + rng.normal(0, xy_std), truth.phi() + rng.normal(0, phi_std)};
}

}  // namespace

Trial generateTrial(const mrpt::maps::COccupancyGridMap2D& map, const LidarProfile& lidar, const TrialParams& p,
                    uint64_t seed) {
  Rng rng(seed);
  const mrpt::maps::COccupancyGridMap2D world = addClutter(map, p.clutter, rng);
  const ClearanceMap clearance(world);
  std::vector<cv::Point> starts;
  cv::findNonZero(clearance.dist() > p.clearance_m, starts);
  if (!p.start_region.empty()) {
    std::vector<cv::Point2f> region;
    for (const auto& v : p.start_region) region.emplace_back(static_cast<float>(v.x), static_cast<float>(v.y));
    const auto outside = [&](const cv::Point& px) {
      const auto xy = pixelToWorld(world, px);
      return cv::pointPolygonTest(region, cv::Point2f(static_cast<float>(xy.x), static_cast<float>(xy.y)), false) < 0;
    };
    starts.erase(std::remove_if(starts.begin(), starts.end(), outside), starts.end());
    if (starts.empty()) throw InputError("trial generator", "no free pose with the required clearance in the start region");
  }
  if (starts.empty()) throw InputError("trial generator", "no free pose with the required clearance in the map");

  const ScanSimulator simulator(lidar, p.scanner);
  Trial t;
  t.seed = seed;
  const auto start_px = starts[static_cast<size_t>(rng.uniformInt(0, static_cast<int>(starts.size()) - 1))];
  const auto start_xy = pixelToWorld(world, start_px);
  mrpt::math::TPose2D pose(start_xy.x, start_xy.y, rng.uniform(-M_PI, M_PI));
  t.truth.push_back(pose);
  t.odometry.emplace_back(0, 0, 0);
  t.distance_m.push_back(0.0);
  t.scans.push_back(simulator.simulate(world, mrpt::poses::CPose2D(pose), rng));

  const double max_turn = p.max_turn_deg * M_PI / 180.0;
  for (int step = 1; step <= p.steps; ++step) {
    mrpt::math::TPose2D next = pose;
    bool moved = false;
    for (int attempt = 0; attempt < p.max_step_attempts && !moved; ++attempt) {
      const double phi = mrpt::math::wrapToPi(pose.phi + rng.uniform(-max_turn, max_turn));
      const mrpt::math::TPose2D cand(pose.x + p.step_length_m * std::cos(phi), pose.y + p.step_length_m * std::sin(phi),
                                     phi);
      if (clearance.segmentClear(pose, cand, p.clearance_m)) {
        next = cand;
        moved = true;
      }
    }
    // Blocked ahead: turn in place by the largest allowed angle and try again next step.
    if (!moved) next.phi = mrpt::math::wrapToPi(pose.phi + max_turn);
    const mrpt::poses::CPose2D increment = mrpt::poses::CPose2D(next) - mrpt::poses::CPose2D(pose);
    t.odometry.push_back(noisyOdometry(increment, p.odometry, rng));
    t.distance_m.push_back(t.distance_m.back() + std::hypot(next.x - pose.x, next.y - pose.y));
    pose = next;
    t.truth.push_back(pose);
    t.scans.push_back(simulator.simulate(world, mrpt::poses::CPose2D(pose), rng));
  }
  return t;
}

Trial kidnapTrial(const Trial& before, const Trial& after) {
  Trial t = before;
  const double walked = before.distance_m.empty() ? 0.0 : before.distance_m.back();
  for (size_t i = 0; i < after.truth.size(); ++i) {
    t.truth.push_back(after.truth[i]);
    t.odometry.push_back(i == 0 ? mrpt::poses::CPose2D() : after.odometry[i]);
    t.distance_m.push_back(walked + after.distance_m[i]);
    t.scans.push_back(after.scans[i]);
  }
  return t;
}

}  // namespace krp
