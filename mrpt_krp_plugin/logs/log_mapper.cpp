// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/logs/log_mapper.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

mrpt::maps::COccupancyGridMap2D mapFromPosedScans(const std::vector<RawlogStep>& steps,
                                                  const std::vector<mrpt::math::TPose2D>& poses,
                                                  const LogMapperParams& p) {
  if (poses.size() != steps.size())
    throw InputError("map from log", std::to_string(poses.size()) + " poses for " + std::to_string(steps.size()) + " scans");
  if (!(p.resolution_m > 0) || !std::isfinite(p.resolution_m)) throw InputError("resolution_m", "must be > 0");
  if (!(p.max_insertion_range_m > 0)) throw InputError("max_insertion_range_m", "must be > 0");
  if (p.every == 0) throw InputError("every", "must be at least 1");
  if (p.first >= steps.size()) throw InputError("first", "is past the log's " + std::to_string(steps.size()) + " scans");

  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  for (std::size_t i = p.first; i < steps.size(); i += p.every) {
    x0 = std::min(x0, poses[i].x), x1 = std::max(x1, poses[i].x);
    y0 = std::min(y0, poses[i].y), y1 = std::max(y1, poses[i].y);
  }
  const double reach = p.max_insertion_range_m + p.margin_m;
  mrpt::maps::COccupancyGridMap2D grid(static_cast<float>(x0 - reach), static_cast<float>(x1 + reach),
                                       static_cast<float>(y0 - reach), static_cast<float>(y1 + reach),
                                       static_cast<float>(p.resolution_m));
  grid.insertionOptions.maxDistanceInsertion = static_cast<float>(p.max_insertion_range_m);
  grid.insertionOptions.considerInvalidRangesAsFreeSpace = false;
  for (std::size_t i = p.first; i < steps.size(); i += p.every) {
    const auto scan = steps[i].observations ? steps[i].observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>()
                                            : nullptr;
    if (!scan) throw InputError("step " + std::to_string(i), "holds no 2D range scan");
    const mrpt::poses::CPose3D robot{mrpt::poses::CPose2D(poses[i])};
    grid.insertObservation(*scan, robot);
  }
  return grid;
}

}  // namespace krp
