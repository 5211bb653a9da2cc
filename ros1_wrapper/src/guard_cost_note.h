// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <optional>
#include <string>

namespace krp::ros1 {

/// What the track-mode node says when the look-alike guard's searches in one filter update took
/// longer than the time between that scan and the one before: the node keeps only the newest
/// scan, so scans are skipped while the guard searches (on a large map with a long-range scanner
/// one search costs tens of ms). Nothing when they fit in the interval, or when the interval is
/// unknown (not positive). `recheck_every_updates` is the node's current setting, named in the
/// advice.
std::optional<std::string> guardCostNote(double search_cpu_s, int searches, double scan_interval_s,
                                         int recheck_every_updates);

/// What the track-mode node says while its converged filter is unverified (MclEstimate::
/// look_alike_unverified): every look-alike search since it converged ran out of
/// `max_search_nodes` with nothing found. Names the budget to raise, and says whether the
/// published covariance is widened (`widened`: look_alike_unverified_is_unsettled).
std::string unverifiedPoseNote(long long max_search_nodes, bool widened);

/// The same while the reason is a search still running, spread over updates at
/// `max_nodes_per_update` nodes each (MclEstimate::look_alike_search_pending): no search since
/// the filter converged has finished yet.
std::string pendingSearchNote(long long max_nodes_per_update, bool widened);

}  // namespace krp::ros1
