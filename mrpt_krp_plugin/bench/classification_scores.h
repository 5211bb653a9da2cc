// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

namespace krp {

/// Precision, recall and F1 of a zone classifier, macro-averaged over the zones (each zone
/// counts the same, whatever its number of samples), as the thesis's Table 4.4 reports them.
struct ClassificationScores {
  double accuracy = 0;
  double precision = 0;
  double recall = 0;
  double f1 = 0;
  int samples = 0;
  int unanswered = 0;  ///< predictions of -1 (no zone): wrong for recall, absent for precision
};

/// `truth[i]` in [0, zones); `predicted[i]` in [-1, zones). A zone never predicted has precision
/// 0 (and F1 0), so a classifier that always answers one zone scores poorly.
ClassificationScores scoreClassification(const std::vector<int>& truth, const std::vector<int>& predicted, int zones);

}  // namespace krp
