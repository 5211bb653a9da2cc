// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/record_groups.h"

#include <map>
#include <string>
#include <tuple>

namespace krp {

std::vector<RecordGroup> groupByWorldLidarMethod(const std::vector<TrialRecord>& records,
                                                 const std::function<bool(const TrialRecord&)>& keep) {
  std::map<std::tuple<std::string, std::string, std::string>, std::size_t> index;
  std::vector<RecordGroup> groups;
  for (const auto& r : records) {
    if (keep && !keep(r)) continue;
    const auto [it, added] = index.emplace(std::make_tuple(r.world, r.lidar, r.method), groups.size());
    if (added) groups.emplace_back();
    groups[it->second].push_back(&r);
  }
  return groups;
}

}  // namespace krp
