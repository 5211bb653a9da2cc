// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace krp {

/// A number for a report table: `precision` significant digits, "-" when it is not finite
/// (a median over no trial, a rate over none).
std::string formatNumber(double value, int precision = 3);

}  // namespace krp
