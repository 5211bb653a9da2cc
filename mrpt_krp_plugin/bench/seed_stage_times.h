// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "mrpt_krp_plugin/bench/bench_runner.h"

namespace krp {

/// Where the relocalizer's time from the first scan went, per world, lidar and method: the mean
/// of each stage over the trials (RelocalizationTimes; a stage that did not run counts 0), so
/// that the stages add up to about the mean total. Only the methods whose relocalizer times its stages
/// (the learned one).
struct SeedStageSummary {
  std::string world, lidar, method;
  int trials = 0;  ///< with stage times
  RelocalizationTimes mean;
  double median_total_ms = 0.0;
};

std::vector<SeedStageSummary> summarizeSeedStages(const std::vector<TrialRecord>& records);

/// The summaries as a Markdown section (an explanation and one table); empty without any.
std::string seedStageTable(const std::vector<SeedStageSummary>& summaries);

/// The stage times' CSV header fields, comma first, for a trials.csv row's end.
std::string seedStageCsvHeader();
/// One record's fields in that order, comma first; empty fields without stage times.
std::string seedStageCsvFields(const TrialRecord& record);

}  // namespace krp
