// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "mrpt_krp_plugin/sim/lidar_profile.h"

#include <string>

namespace krp {

/// How a submap is turned before the models see it.
enum class SubmapOrientation {
  /// The robot's forward axis up: the models must recognise a place from any heading.
  kHeadingUp,
  /// The walls along the image's rows and columns, estimated from the scan (submap/wall_axes.h):
  /// a place looks the same from every heading up to a quarter turn, and the relocalizer tries
  /// the four turns. Needs walls that mostly meet at right angles.
  kWallAxes,
};

/// "heading_up" or "wall_axes", as the dataset card and manifest.json write it.
std::string orientationName(SubmapOrientation o);
/// The inverse of orientationName; InputError(what, ...) naming the choices for anything else.
SubmapOrientation parseOrientation(const std::string& name, const std::string& what);

/// The submap's extent and cell count. The cell count is the models' input size, so the
/// resolution is size_m / size_px.
struct SubmapParams {
  double size_m = 16.0;  ///< side of the square submap [m]
  int size_px = 160;     ///< cells per side (= image pixels) [px]
  /// Beams without a return (at or beyond max range, or flagged invalid) carry free space up
  /// to this fraction of max range. Off by default: lidars flag dropouts (glass, black or
  /// grazing surfaces) the same way as open space, and inside a room each such beam painted a
  /// free spoke through the walls that drowned the room's shape (the zone classifier learned
  /// nothing from such images: 73 % validation accuracy on office_two_zone, chance being 57 %).
  double no_return_free_fraction = 0.0;
  /// Each scan's hit points are marked this many cells thick, so one-cell walls survive
  /// the rasterization of slightly noisy rays [cells].
  int hit_radius_cells = 0;
  SubmapOrientation orientation = SubmapOrientation::kHeadingUp;

  double resolutionM() const { return size_m / size_px; }
};

/// Submap parameters sized for a lidar: the side covers the lidar's diameter of view, within
/// [min_side_m, max_side_m] (a 3.5 m LDS-01 gets 8 m, a 12 m scanner 24 m, a 25 m one 24 m:
/// beyond that a 160 px image would lose thin walls to resolution).
SubmapParams submapParamsForLidar(const LidarProfile& lidar, int size_px = 160, double min_side_m = 8.0,
                                  double max_side_m = 24.0);

/// Throws InputError if the parameters cannot make a submap.
void validateSubmapParams(const SubmapParams& p);

}  // namespace krp
