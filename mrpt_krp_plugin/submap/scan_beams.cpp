// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/scan_beams.h"

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

ScanBeams scanBeams(const mrpt::obs::CObservation2DRangeScan& scan) {
  const size_t n = scan.getScanSize();
  const std::string what = "scan '" + scan.sensorLabel + "'";
  if (n < 2) throw InputError(what, "has " + std::to_string(n) + " beams (at least 2 needed)");
  if (!(scan.aperture > 0) || !std::isfinite(scan.aperture) || scan.aperture > 2 * M_PI + 1e-3)
    throw InputError(what, "aperture must be in (0, 2 pi]");
  if (!(scan.maxRange > 0) || !std::isfinite(scan.maxRange)) throw InputError(what, "max range must be > 0");
  ScanBeams out;
  out.beams.reserve(n);
  const double step = scan.aperture / static_cast<double>(n - 1);
  for (size_t i = 0; i < n; ++i) {
    const double k = scan.rightToLeft ? static_cast<double>(i) : static_cast<double>(n - 1 - i);
    Beam b;
    b.angle_rad = -0.5 * scan.aperture + k * step;
    const double r = scan.getScanRange(i);
    if (!std::isfinite(r) || r < 0) {
      ++out.rejected;
      continue;
    }
    b.range_m = r;
    b.hit = scan.getScanRangeValidity(i) && r < scan.maxRange;
    if (!b.hit) ++out.no_return;
    out.beams.push_back(b);
  }
  return out;
}

}  // namespace krp
