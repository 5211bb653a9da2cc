// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

namespace krp {

/// A 2D lidar's geometry and error model.
struct LidarProfile {
  std::string name;
  double fov_rad = 0.0;               ///< field of view [rad]; 2*pi for a 360 deg scanner
  int beams = 0;                      ///< beams per scan
  double max_range_m = 0.0;           ///< returns at or beyond this are "no return" [m]
  double range_noise_std_m = 0.01;    ///< Gaussian range noise [m]
  double dropout_probability = 0.01;  ///< chance a beam returns nothing [0..1]
  double mount_x_m = 0.0;             ///< sensor position ahead of the robot centre [m]

  /// MRPT's aperture: spacing is aperture/(beams-1), so a 360 deg scanner that does not
  /// repeat its first beam has aperture 2*pi*(beams-1)/beams.
  double mrptAperture() const;
  bool isFullCircle() const;
};

/// The built-in profiles: `lds01` (TurtleBot3 LDS-01: 360 deg, 360 beams, 3.5 m),
/// `omni_12m` (360 deg, 720 beams, 12 m), `safety_270` (270 deg, 541 beams, 25 m).
const std::vector<LidarProfile>& builtinLidarProfiles();

/// A built-in profile by name; throws InputError listing the names for an unknown one.
LidarProfile lidarProfileByName(const std::string& name);

}  // namespace krp
