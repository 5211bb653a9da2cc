// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/map_sanity.h"

#include <cmath>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

void checkGridGeometry(const GridGeometry& g, const MapSanityLimits& limits, const std::string& input) {
  if (!std::isfinite(g.origin_x_m) || !std::isfinite(g.origin_y_m))
    throw InputError(input, "origin holds a NaN or infinite value");
  if (!std::isfinite(g.resolution_m) || g.resolution_m < limits.min_resolution_m ||
      g.resolution_m > limits.max_resolution_m) {
    std::ostringstream s;
    s << "resolution " << g.resolution_m << " m is not a plausible cell size (accepted: " << limits.min_resolution_m
      << " to " << limits.max_resolution_m << " m)";
    throw InputError(input, s.str());
  }
  if (!(g.width_cells >= 1 && g.height_cells >= 1)) throw InputError(input, "the grid is empty (0 cells)");
  if (g.width_cells * g.height_cells > limits.max_cells) {
    std::ostringstream s;
    s << g.width_cells << " x " << g.height_cells << " cells is larger than the limit of " << limits.max_cells;
    throw InputError(input, s.str());
  }
  const double far_x = g.origin_x_m + g.width_cells * g.resolution_m;
  const double far_y = g.origin_y_m + g.height_cells * g.resolution_m;
  for (const double c : {g.origin_x_m, g.origin_y_m, far_x, far_y}) {
    if (std::abs(c) > limits.max_abs_coordinate_m) {
      std::ostringstream s;
      s << "the map reaches " << c << " m from the origin of its frame; at most " << limits.max_abs_coordinate_m
        << " m is accepted";
      throw InputError(input, s.str());
    }
  }
}

}  // namespace krp
