// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/dataset/zone_pose_sampler.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {

ZonePoseSampler::ZonePoseSampler(const mrpt::maps::COccupancyGridMap2D& map, const std::vector<Zone>& zones,
                                 double clearance_m)
    : map_(map), cells_(zones.size()) {
  const cv::Mat clearance = freeClearanceM(map);
  const cv::Mat labels = rasterizeZones(map, zones);
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c) {
      const int z = labels.at<int>(r, c);
      if (z >= 0 && clearance.at<float>(r, c) >= clearance_m) cells_[static_cast<size_t>(z)].emplace_back(c, r);
    }
  for (size_t z = 0; z < zones.size(); ++z)
    if (cells_[z].empty())
      throw InputError("zone '" + zones[z].name + "'", "has no free cell " + std::to_string(clearance_m) +
                                                           " m clear of walls to sample robot poses from");
}

mrpt::poses::CPose2D ZonePoseSampler::sample(size_t zone, Rng& rng) const {
  const auto& cells = cells_.at(zone);
  const cv::Point px = cells[static_cast<size_t>(rng.uniformInt(0, static_cast<int>(cells.size()) - 1))];
  // Anywhere inside the chosen cell, not just its centre.
  const double half = 0.5 * map_.getResolution();
  const auto centre = pixelToWorld(map_, px);
  return {centre.x + rng.uniform(-half, half), centre.y + rng.uniform(-half, half), rng.uniform(-M_PI, M_PI)};
}

}  // namespace krp
