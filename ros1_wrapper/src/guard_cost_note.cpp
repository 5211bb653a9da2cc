// SPDX-License-Identifier: BSD-3-Clause
#include "guard_cost_note.h"

#include <iomanip>
#include <sstream>
#include <string>

namespace krp::ros1 {

namespace {
/// "pose unverified: <why>", and how the pose is published.
std::string unverifiedNote(const std::string& why, bool widened) {
  return "pose unverified: " + why +
         (widened ? "; the published covariance is widened"
                  : "; look_alike_unverified_is_unsettled is off, so the published covariance is not widened");
}
}  // namespace

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

std::string unverifiedPoseNote(long long max_search_nodes, bool widened) {
  return unverifiedNote("every look-alike search since the filter converged ran out of look_alike_max_search_nodes (" +
                            std::to_string(max_search_nodes) +
                            ") with nothing found, so nothing rules out a look-alike place",
                        widened);
}

std::string pendingSearchNote(long long max_nodes_per_update, bool widened) {
  return unverifiedNote(
      "no look-alike search since the filter converged has finished yet; one is running, "
      "look_alike_max_nodes_per_update (" +
          std::to_string(max_nodes_per_update) + ") nodes per update, so nothing rules out a look-alike place yet",
      widened);
}

}  // namespace krp::ros1
