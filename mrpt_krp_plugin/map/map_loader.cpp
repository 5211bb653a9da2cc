// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/map_loader.h"

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/mrpt_gridmap_reader.h"

namespace krp {
namespace {
bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
}  // namespace

OccupancyMap loadOccupancyMap(const std::string& path, const MapLoadParams& params) {
  if (endsWith(path, ".yaml") || endsWith(path, ".yml")) return readRosMap(path, params.limits);
  if (endsWith(path, ".gridmap") || endsWith(path, ".gridmap.gz")) return readMrptGridmap(path, params.limits);
  if (endsWith(path, ".bt") || endsWith(path, ".ot")) return readOctomapSlice(path, params.octomap, params.limits);
  throw InputError(path, "unsupported map format (expected .yaml/.yml, .gridmap, .gridmap.gz, .bt or .ot)");
}

}  // namespace krp
