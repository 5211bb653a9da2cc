// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <yaml-cpp/yaml.h>

#include <ostream>
#include <string>
#include <vector>

namespace krp {

/// Reads a YAML list of [x, y] points (finite numbers). Throws InputError naming `path` and
/// `owner` (e.g. "zone 'lobby'") if a point is missing, malformed, NaN or infinite.
std::vector<mrpt::math::TPoint2D> readYamlPoints(const YAML::Node& list, const std::string& path,
                                                 const std::string& owner, size_t min_points);

/// Writes points as a flow list: [[x0, y0], [x1, y1], ...].
void writeYamlPoints(std::ostream& o, const std::vector<mrpt::math::TPoint2D>& points);

}  // namespace krp
