// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/see_through_speed.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/common/statistics.h"
#include "mrpt_krp_plugin/common/thread_cpu_time.h"
#include "mrpt_krp_plugin/filter/see_through.h"

namespace krp {
namespace {

// The particle cloud's draws, a stream of the trial seed apart from the trial's own.
constexpr uint64_t kCloudStream = 0x636c6f7564ull;  // "cloud"

// The fastest of `repeats` charges of the whole cloud by `count` [s], and the counts.
template <typename Count>
double fastestCharge(const std::vector<mrpt::math::TPose2D>& cloud, int repeats, Count count, std::vector<int>* counts) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeats; ++r) {
    counts->assign(cloud.size(), 0);
    const double t0 = threadCpuSeconds();
    for (size_t k = 0; k < cloud.size(); ++k) (*counts)[k] = count(cloud[k]);
    best = std::min(best, threadCpuSeconds() - t0);
  }
  return best;
}

}  // namespace

SeeThroughSpeed measureSeeThroughSpeed(const mrpt::maps::COccupancyGridMap2D& map, const LidarProfile& lidar,
                                       const SeeThroughSpeedParams& params, const std::function<void()>& on_scan) {
  if (params.scans < 1 || params.particles < 1 || params.repeats < 1)
    throw std::invalid_argument("measureSeeThroughSpeed: scans, particles and repeats must be at least 1");
  if (!(params.spread_m >= 0.0) || !(params.spread_deg >= 0.0))
    throw std::invalid_argument("measureSeeThroughSpeed: the spreads must be >= 0");
  const SeeThroughPenalty penalty(map, params.filter.sensor, params.filter.see_through);
  TrialParams trial_params = params.trial;
  trial_params.steps = 0;  // the first scan: the update a seeded prior is weighed in
  SeeThroughSpeed out;
  std::vector<double> one_ms, side_ms, ratios;
  double one_total = 0.0, side_total = 0.0, seen_through = 0.0;
  for (int i = 0; i < params.scans; ++i) {
    const uint64_t seed = params.seed + static_cast<uint64_t>(i);
    const auto trial = generateTrial(map, lidar, trial_params, seed);
    const auto scan = penalty.forScan(*trial.scans.front());
    const auto& truth = trial.truth.front();
    Rng rng(deriveSeed(seed, kCloudStream));
    std::vector<mrpt::math::TPose2D> cloud(static_cast<size_t>(params.particles));
    for (auto& p : cloud)
      p = {rng.normal(truth.x, params.spread_m), rng.normal(truth.y, params.spread_m),
           mrpt::math::wrapToPi(rng.normal(truth.phi, params.spread_deg * M_PI / 180.0))};
    std::vector<int> one_counts, side_counts;
    const auto one = [&] {
      return fastestCharge(cloud, params.repeats, [&](const auto& p) { return scan.countOneRayAtATime(p); }, &one_counts);
    };
    const auto side = [&] {
      return fastestCharge(cloud, params.repeats, [&](const auto& p) { return scan.count(p); }, &side_counts);
    };
    double one_s = 0.0, side_s = 0.0;
    if (i % 2 == 0) {
      one_s = one();
      side_s = side();
    } else {
      side_s = side();
      one_s = one();
    }
    for (size_t k = 0; k < cloud.size(); ++k) {
      out.differing += one_counts[k] != side_counts[k] ? 1 : 0;
      seen_through += one_counts[k];
    }
    one_ms.push_back(one_s * 1e3);
    side_ms.push_back(side_s * 1e3);
    ratios.push_back(side_s > 0.0 ? one_s / side_s : 0.0);
    one_total += one_s;
    side_total += side_s;
    out.checked_beams = scan.checked();
    out.particle_charges += params.particles;
    ++out.scans;
    if (on_scan) on_scan();
  }
  out.median_ms_one_at_a_time = median(one_ms);
  out.median_ms_side_by_side = median(side_ms);
  out.median_ratio = median(ratios);
  out.total_ratio = side_total > 0.0 ? one_total / side_total : 0.0;
  out.mean_seen_through = seen_through / static_cast<double>(out.particle_charges);
  return out;
}

}  // namespace krp
