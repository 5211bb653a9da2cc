// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/reliability.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace krp {

std::vector<double> defaultReliabilityEdges() { return {0.0, 0.5, 0.8, 0.9, 0.95, 0.99, 1.0}; }

std::vector<ReliabilityBin> reliabilityTable(const std::vector<ConfidenceOutcome>& answers, const std::vector<double>& edges) {
  if (edges.size() < 2) throw std::invalid_argument("reliability table: at least two bin edges");
  std::vector<ReliabilityBin> bins(edges.size() - 1);
  for (std::size_t b = 0; b < bins.size(); ++b) {
    if (!(edges[b] < edges[b + 1])) throw std::invalid_argument("reliability table: bin edges must ascend");
    bins[b].low = edges[b];
    bins[b].high = edges[b + 1];
  }
  std::vector<double> sums(bins.size(), 0.0);
  for (const auto& a : answers) {
    for (std::size_t b = 0; b < bins.size(); ++b) {
      const bool last = b + 1 == bins.size();
      if (a.confidence >= bins[b].low && (a.confidence < bins[b].high || (last && a.confidence <= bins[b].high))) {
        ++bins[b].answers;
        bins[b].right += a.right ? 1 : 0;
        sums[b] += a.confidence;
        break;
      }
    }
  }
  for (std::size_t b = 0; b < bins.size(); ++b)
    bins[b].mean_confidence = bins[b].answers ? sums[b] / bins[b].answers : std::nan("");
  return bins;
}

double expectedCalibrationError(const std::vector<ReliabilityBin>& bins) {
  double weighted = 0.0;
  int total = 0;
  for (const auto& b : bins) {
    if (b.answers == 0) continue;
    weighted += b.answers * std::abs(static_cast<double>(b.right) / b.answers - b.mean_confidence);
    total += b.answers;
  }
  return total ? weighted / total : std::nan("");
}

std::string reliabilityMarkdown(const std::vector<ReliabilityBin>& bins) {
  std::ostringstream o;
  o << std::setprecision(3);
  o << "| confidence | answers | mean confidence | right |\n|---|---|---|---|\n";
  for (std::size_t i = 0; i < bins.size(); ++i) {
    const auto& b = bins[i];
    o << "| [" << b.low << ", " << b.high << (i + 1 == bins.size() ? "]" : ")") << " | " << b.answers << " | ";
    if (b.answers)
      o << b.mean_confidence << " | " << 100.0 * b.right / b.answers << " % (" << b.right << ") |\n";
    else
      o << "- | - |\n";
  }
  o << "\nExpected calibration error: " << expectedCalibrationError(bins) << "\n";
  return o.str();
}

}  // namespace krp
