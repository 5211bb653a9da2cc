// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/classification_scores.h"

#include <stdexcept>

namespace krp {

ClassificationScores scoreClassification(const std::vector<int>& truth, const std::vector<int>& predicted, int zones) {
  if (truth.size() != predicted.size()) throw std::invalid_argument("scoreClassification: sizes differ");
  if (zones <= 0) throw std::invalid_argument("scoreClassification: no zones");
  std::vector<int> true_positive(zones, 0), predicted_as(zones, 0), actual(zones, 0);
  ClassificationScores s;
  s.samples = static_cast<int>(truth.size());
  int right = 0;
  for (size_t i = 0; i < truth.size(); ++i) {
    if (truth[i] < 0 || truth[i] >= zones || predicted[i] < -1 || predicted[i] >= zones)
      throw std::invalid_argument("scoreClassification: zone index out of range");
    ++actual[truth[i]];
    if (predicted[i] < 0) {
      ++s.unanswered;
      continue;
    }
    ++predicted_as[predicted[i]];
    if (predicted[i] == truth[i]) ++true_positive[truth[i]], ++right;
  }
  for (int z = 0; z < zones; ++z) {
    const double p = predicted_as[z] ? double(true_positive[z]) / predicted_as[z] : 0.0;
    const double r = actual[z] ? double(true_positive[z]) / actual[z] : 0.0;
    s.precision += p / zones;
    s.recall += r / zones;
    s.f1 += (p + r > 0 ? 2 * p * r / (p + r) : 0.0) / zones;
  }
  s.accuracy = s.samples ? double(right) / s.samples : 0.0;
  return s;
}

}  // namespace krp
