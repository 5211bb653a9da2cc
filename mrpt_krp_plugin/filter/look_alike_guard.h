// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <memory>
#include <optional>

#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"

namespace krp {

/// When the particle filter has just converged, a look-alike place may fit the scan as well: in
/// a mirror-like building the particles can collapse onto the wrong wing, and the scan fit there
/// stays high, so kidnap detection never fires. The guard asks the correlative matcher for a
/// place that fits at least as well as the filter's mean (the mean's own score as the bar, so
/// most branches are pruned) and, when there is one, moves a share of the particles there: the
/// next scans decide between the two, and until they do the filter does not claim a pose.
struct LookAlikeGuardParams {
  /// The filter counts as converged (and is checked, once per convergence) when the larger of
  /// its x and y std (covariance diagonal) is below this and its heading std below the next
  /// [m], [deg]. The bench's "confident" has the same thresholds but takes the largest
  /// eigenvalue of the xy covariance, so a cloud stretched along a diagonal can count as
  /// converged here a little before the bench calls it confident.
  double converged_std_m = 0.5;
  double converged_std_deg = 10.0;
  /// A place counts as a look-alike when it scores at least the mean's matcher score minus this
  /// [0..1]. Zero: only places that fit as well or better; a converged filter on the right pose
  /// is then rarely disturbed by a place that fits a little worse.
  double score_margin = 0.0;
  double moved_share = 0.5;  ///< share of the particles moved to the look-alike place [0..1]
  double spread_m = 0.1;     ///< std of the moved particles around it, position [m]
  double spread_deg = 3.0;   ///< ... and heading [deg]
};

class LookAlikeGuard {
 public:
  LookAlikeGuard(std::shared_ptr<const CorrelativeMatcher> matcher, LookAlikeGuardParams params = {});

  /// A place other than `pose` that fits `scan` at least as well (by the bar above), if any.
  std::optional<mrpt::math::TPose2D> lookAlike(const mrpt::obs::CObservation2DRangeScan& scan,
                                               const mrpt::math::TPose2D& pose) const;
  const LookAlikeGuardParams& params() const { return params_; }

 private:
  std::shared_ptr<const CorrelativeMatcher> matcher_;
  LookAlikeGuardParams params_;
};

}  // namespace krp
