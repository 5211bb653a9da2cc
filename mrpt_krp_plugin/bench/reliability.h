// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

namespace krp {

/// One confidence bin of a reliability table: what the relocalizer claimed and how often it
/// was right.
struct ReliabilityBin {
  double low = 0.0, high = 0.0;  ///< confidences in [low, high)
  int answers = 0;
  int right = 0;
  double mean_confidence = 0.0;  ///< NaN for an empty bin
};

/// One answer: the best hypothesis's confidence and whether it was right.
struct ConfidenceOutcome {
  double confidence = 0.0;
  bool right = false;
};

/// Default bin edges: coarse where "not localized" is said, fine near the 0.8 threshold and above.
std::vector<double> defaultReliabilityEdges();

/// Bins the answers by confidence (edges ascending; the last bin includes its upper edge).
std::vector<ReliabilityBin> reliabilityTable(const std::vector<ConfidenceOutcome>& answers,
                                             const std::vector<double>& edges = defaultReliabilityEdges());

/// Expected calibration error: the answer-weighted mean of |right rate - mean confidence| over
/// the bins; NaN without answers. 0 = perfectly calibrated.
double expectedCalibrationError(const std::vector<ReliabilityBin>& bins);

/// The table as Markdown rows (`| bin | answers | mean confidence | right |`) with the ECE below.
std::string reliabilityMarkdown(const std::vector<ReliabilityBin>& bins);

}  // namespace krp
