// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace krp {

/// One beam of a 2D scan in the sensor frame.
struct Beam {
  double angle_rad = 0;  ///< counter-clockwise from the sensor's forward axis [rad]
  double range_m = 0;    ///< measured range [m]; meaningful only if `hit`
  bool hit = false;      ///< a return shorter than max range
};

/// A scan's beams, with what the scan says about each.
struct ScanBeams {
  std::vector<Beam> beams;
  int no_return = 0;  ///< beams flagged invalid or at/after max range (free space, no obstacle)
  int rejected = 0;   ///< beams with NaN, infinite or negative ranges (ignored entirely)
};

/// Reads a scan's beams in the sensor frame, honouring `rightToLeft` and `aperture`.
/// Throws InputError for a scan that cannot be read (no beams, non-positive aperture or max range).
ScanBeams scanBeams(const mrpt::obs::CObservation2DRangeScan& scan);

}  // namespace krp
