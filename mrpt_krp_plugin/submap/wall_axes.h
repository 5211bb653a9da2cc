// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace krp {

/// How the dominant wall direction of a scan or a map is estimated. Indoor walls mostly meet
/// at right angles, so a direction is only known modulo 90 deg.
struct WallAxesParams {
  /// Consecutive hit points farther apart than this are not on one wall [m].
  double max_neighbour_gap_m = 1.5;
  /// Consecutive hit points closer than this give too noisy a direction and are skipped [m].
  double min_neighbour_gap_m = 0.6;
  /// Width of the direction histogram's bins [deg].
  double bin_deg = 1.0;
  /// The histogram is smoothed with a circular box this wide before its peak is taken [deg].
  double smoothing_deg = 5.0;
  /// The peak's share of all wall length under which no direction is reported: a scan of
  /// clutter or of round walls has no axes, and a guessed one would only mislead.
  double min_support = 0.2;
  /// Gaussian blur of the map's occupied cells before their edges are measured [cells].
  double map_blur_cells = 1.5;
};

/// The dominant wall direction, modulo 90 deg.
struct WallAxes {
  double angle_rad = 0;  ///< in [-45, 45) deg, in the frame of the input (robot frame for a scan)
  double support = 0;    ///< share of the wall length within the peak's smoothing window, [0, 1]
  bool found = false;    ///< support >= min_support
};

/// From the segments between neighbouring hits of one scan, weighted by their length, in the
/// robot frame (the scan's sensor pose is applied).
WallAxes scanWallAxes(const mrpt::obs::CObservation2DRangeScan& scan, const WallAxesParams& params = {});

/// From the edges of the map's occupied cells (occupiedMask, image gradients), in the map frame.
WallAxes mapWallAxes(const mrpt::maps::COccupancyGridMap2D& map, const WallAxesParams& params = {});

/// The four headings of the robot in an image whose axes follow the walls: with walls at
/// `scan_axes.angle_rad` in the robot frame, drawing the robot at heading -angle + k * 90 deg
/// puts the walls along the image's rows and columns. One of the four is the robot's heading
/// relative to the map's wall axes; which one, the scan alone cannot tell. Heading 0 is along
/// the image's columns (to the right), counter-clockwise positive.
std::vector<double> wallAlignedImageHeadings(const WallAxes& scan_axes);

/// The four headings of a robot in the map at which the scan's walls (`scan_axes`, robot frame)
/// lie along the map's (`map_axes`, map frame): map - scan + k * 90 deg, in [-180, 180) deg. In a
/// building whose walls meet at right angles, a pose at any other heading crosses the map's walls
/// with the scan's.
std::vector<double> wallAlignedMapHeadings(const WallAxes& scan_axes, const WallAxes& map_axes);

/// The candidate closest to `heading_rad` (angles compared modulo 360 deg).
double nearestHeading(const std::vector<double>& candidates_rad, double heading_rad);

}  // namespace krp
