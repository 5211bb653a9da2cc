// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/bench/bench_runner.h"

namespace krp {

/// One method's trials on one world and lidar, split by their path verdict: what it achieves
/// where the scans can tell the truth apart, and where they cannot.
struct PathAmbiguitySplit {
  std::string world, lidar, method;
  struct Counts {
    int trials = 0, success = 0, confident_wrong = 0, confident_right = 0;
  };
  Counts told_apart, ambiguous, misleading;
};

/// The splits of every (world, lidar, method) whose trials were checked, in the order their
/// groups first appear.
std::vector<PathAmbiguitySplit> splitByPathAmbiguity(const std::vector<TrialRecord>& records);

/// The Markdown section (heading, what it means, how many trials each verdict got, and each
/// method's outcome per verdict); empty when no trial was checked.
std::string pathAmbiguitySection(const std::vector<PathAmbiguitySplit>& splits, const PathAmbiguityParams& params);

}  // namespace krp
