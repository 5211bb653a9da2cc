// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

namespace krp {

/// The q-quantile of `values` (q in [0, 1]), interpolating linearly between the two nearest ranks
/// (numpy's default), so that quantile(v, 0.5) is the median: every report and bench in the
/// project uses this one definition. NaN for no values; std::invalid_argument for q outside [0, 1].
double quantile(std::vector<double> values, double q);

/// quantile(values, 0.5): the middle value, or the mean of the two middle ones.
double median(std::vector<double> values);

}  // namespace krp
