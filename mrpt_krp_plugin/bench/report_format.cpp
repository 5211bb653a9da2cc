// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/report_format.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace krp {

std::string formatNumber(double value, int precision) {
  if (!std::isfinite(value)) return "-";
  std::ostringstream o;
  o << std::setprecision(precision) << value;
  return o.str();
}

}  // namespace krp
