// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace krp {

/// Limits that turn an absurd map into an error instead of an out-of-memory crash or an
/// assertion deep inside MRPT.
struct MapSanityLimits {
  double max_cells = 2.0e8;          ///< largest accepted width * height [cells]
  double min_resolution_m = 1e-3;    ///< finest accepted cell size [m]
  double max_resolution_m = 10.0;    ///< coarsest accepted cell size [m]
  /// Largest accepted |coordinate| of any map corner [m]. MRPT keeps the map's extent in float:
  /// at 1e5 m a float still resolves 8 mm, well below any cell size.
  double max_abs_coordinate_m = 1.0e5;
};

/// A grid's geometry as read from a file or a message, before any memory is allocated for it.
struct GridGeometry {
  double origin_x_m = 0, origin_y_m = 0;  ///< the lower-left corner [m]
  double resolution_m = 0;
  double width_cells = 0, height_cells = 0;
};

/// InputError naming `input` for a non-finite value, an empty grid, a cell size outside the
/// limits, more cells than the limit, or a corner beyond max_abs_coordinate_m.
void checkGridGeometry(const GridGeometry& g, const MapSanityLimits& limits, const std::string& input);

}  // namespace krp
