// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/zones/zone.h"

namespace krp {

/// Reads `zones.yaml`:
///   zones:
///     - name: lobby
///       polygon: [[x0, y0], [x1, y1], [x2, y2], ...]   # grid-frame metres
/// Throws InputError naming the file, the zone and the problem (unknown keys included).
std::vector<Zone> readZonesYaml(const std::string& path);

/// Writes zones in the same format, atomically.
void writeZonesYaml(const std::vector<Zone>& zones, const std::string& path);

}  // namespace krp
