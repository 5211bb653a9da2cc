// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "mrpt_krp_plugin/sim/lidar_profile.h"

namespace krp {

/// A user's own lidar, for a scanner none of the built-in profiles matches. File format
/// (`*.yaml`; every key but the first three optional, with LidarProfile's defaults):
///   name: sick_lms200            # default: the file's name without .yaml
///   fov_deg: 180                 # field of view, (0, 360]
///   beams: 361                   # beams per scan, 2 or more
///   max_range_m: 80              # returns at or beyond this are "no return"
///   range_noise_std_m: 0.01      # Gaussian range noise
///   dropout_probability: 0.01    # chance a beam returns nothing
///   mount_x_m: 0.0               # sensor ahead of the robot centre
/// Throws InputError naming the file for a missing or unknown key, or a value out of range.
LidarProfile readLidarProfileFile(const std::string& path);

/// Writes `profile` in the format above, atomically (what a model folder keeps of its lidar).
void writeLidarProfileFile(const LidarProfile& profile, const std::string& path);

/// `name_or_file` ending in .yaml or .yml: that file (readLidarProfileFile); otherwise a built-in
/// profile by name. The error for an unknown name lists the built-in ones and says a file works too.
LidarProfile lidarProfile(const std::string& name_or_file);

/// Whether `name_or_file` names a profile file rather than a built-in profile.
bool isLidarProfileFile(const std::string& name_or_file);

}  // namespace krp
