// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <vector>

#include "mrpt_krp_plugin/bench/bench_runner.h"

namespace krp {

/// The trials of one method on one world and lidar.
using RecordGroup = std::vector<const TrialRecord*>;

/// Records grouped by (world, lidar, method), the groups in the order their first record
/// appears; only the records `keep` accepts (all when it is empty). Every group is non-empty.
std::vector<RecordGroup> groupByWorldLidarMethod(const std::vector<TrialRecord>& records,
                                                 const std::function<bool(const TrialRecord&)>& keep = {});

}  // namespace krp
