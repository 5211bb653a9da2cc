// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "mrpt_krp_plugin/bench/thesis_comparison.h"

namespace krp {

/// REPORT.md of a comparison: the command, the setup, Table 4.4's and Table 4.5's analogues,
/// and the thesis's own figures beside them.
std::string thesisComparisonMarkdown(const ThesisComparison& c, const std::string& command);

/// One row per held-out sample: truth, each classifier's zone, each alignment's pose.
std::string thesisComparisonCsv(const ThesisComparison& c);

}  // namespace krp
