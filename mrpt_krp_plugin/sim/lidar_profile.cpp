// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/sim/lidar_profile.h"

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kFullCircleTolerance = 1e-6;
}  // namespace

bool LidarProfile::isFullCircle() const { return std::abs(fov_rad - kTwoPi) < kFullCircleTolerance; }

double LidarProfile::mrptAperture() const {
  if (isFullCircle()) return kTwoPi * (beams - 1) / beams;
  return fov_rad;
}

const std::vector<LidarProfile>& builtinLidarProfiles() {
  static const std::vector<LidarProfile> profiles = {
      // ROBOTIS LDS-01 datasheet: 360 deg, 1 deg steps, 0.12-3.5 m, +-15 mm accuracy to 0.5 m, 5 % beyond.
      {"lds01", kTwoPi, 360, 3.5, 0.015, 0.02, 0.0},
      // A typical 360 deg indoor scanner (RPLIDAR-class): 0.5 deg steps, 12 m.
      {"omni_12m", kTwoPi, 720, 12.0, 0.01, 0.01, 0.0},
      // A 270 deg safety scanner (SICK/Hokuyo-class): 0.5 deg steps, 25 m, front-mounted.
      {"safety_270", 270.0 * M_PI / 180.0, 541, 25.0, 0.01, 0.01, 0.25},
  };
  return profiles;
}

LidarProfile lidarProfileByName(const std::string& name) {
  std::string known;
  for (const auto& p : builtinLidarProfiles()) {
    if (p.name == name) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw InputError("lidar profile '" + name + "'", "unknown (built-in: " + known + ")");
}

}  // namespace krp
