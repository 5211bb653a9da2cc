// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/submap_params.h"

#include <algorithm>
#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

SubmapParams submapParamsForLidar(const LidarProfile& lidar, int size_px, double min_side_m, double max_side_m) {
  SubmapParams p;
  p.size_px = size_px;
  // A little over the diameter so the farthest returns fall inside, then whole metres.
  constexpr double kDiameterMargin = 1.1;
  p.size_m = std::clamp(std::ceil(2.0 * lidar.max_range_m * kDiameterMargin), min_side_m, max_side_m);
  return p;
}

std::string orientationName(SubmapOrientation o) {
  return o == SubmapOrientation::kWallAxes ? "wall_axes" : "heading_up";
}

SubmapOrientation parseOrientation(const std::string& name, const std::string& what) {
  if (name == "heading_up") return SubmapOrientation::kHeadingUp;
  if (name == "wall_axes") return SubmapOrientation::kWallAxes;
  throw InputError(what, "submap orientation '" + name + "' is not one of heading_up, wall_axes");
}

void validateSubmapParams(const SubmapParams& p) {
  if (!(p.size_m > 0 && std::isfinite(p.size_m))) throw InputError("submap parameters", "size_m must be > 0");
  if (p.size_px < 16 || p.size_px > 4096) throw InputError("submap parameters", "size_px must be in [16, 4096]");
  if (!(p.no_return_free_fraction >= 0 && p.no_return_free_fraction <= 1))
    throw InputError("submap parameters", "no_return_free_fraction must be in [0, 1]");
  if (p.hit_radius_cells < 0 || p.hit_radius_cells > 4)
    throw InputError("submap parameters", "hit_radius_cells must be in [0, 4]");
}

}  // namespace krp
