// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/zones/yaml_points.h"

#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

std::vector<mrpt::math::TPoint2D> readYamlPoints(const YAML::Node& list, const std::string& path,
                                                 const std::string& owner, size_t min_points) {
  if (!list || !list.IsSequence() || list.size() < min_points)
    throw InputError(path, owner + ": must list at least " + std::to_string(min_points) + " [x, y] points");
  std::vector<mrpt::math::TPoint2D> points;
  for (const auto& pt : list) {
    if (!pt.IsSequence() || pt.size() != 2) throw InputError(path, owner + ": a point is not [x, y]");
    double x, y;
    try {
      x = pt[0].as<double>();
      y = pt[1].as<double>();
    } catch (const YAML::Exception&) {
      throw InputError(path, owner + ": a coordinate is not a number");
    }
    if (!std::isfinite(x) || !std::isfinite(y)) throw InputError(path, owner + ": NaN or infinite point");
    points.push_back({x, y});
  }
  return points;
}

void writeYamlPoints(std::ostream& o, const std::vector<mrpt::math::TPoint2D>& points) {
  o << "[";
  for (size_t i = 0; i < points.size(); ++i) o << (i ? ", " : "") << "[" << points[i].x << ", " << points[i].y << "]";
  o << "]";
}

}  // namespace krp
