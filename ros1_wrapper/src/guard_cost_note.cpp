// SPDX-License-Identifier: BSD-3-Clause
#include "guard_cost_note.h"

#include <iomanip>
#include <sstream>

namespace krp::ros1 {

std::optional<std::string> guardCostNote(double search_cpu_s, int searches, double scan_interval_s,
                                         int recheck_every_updates) {
  if (searches <= 0 || !(scan_interval_s > 0.0) || search_cpu_s <= scan_interval_s) return std::nullopt;
  constexpr double kMsPerS = 1000.0;
  std::ostringstream s;
  s << std::fixed << std::setprecision(0) << "the look-alike guard's " << searches << " search(es) took "
    << search_cpu_s * kMsPerS << " ms of CPU, more than the " << scan_interval_s * kMsPerS
    << " ms between scans: scans are skipped while it searches; look_alike_recheck_every_updates ("
    << recheck_every_updates << ") set higher searches less often";
  return s.str();
}

}  // namespace krp::ros1
