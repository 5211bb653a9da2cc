// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <memory>
#include <optional>
#include <vector>

#include "mrpt_krp_plugin/filter/filter_spread.h"
#include "mrpt_krp_plugin/filter/rival_test.h"
#include "mrpt_krp_plugin/filter/see_through.h"
#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"

namespace krp {

/// When the particle filter has converged, a look-alike place may fit the scan as well: in a
/// mirror-like building the particles can collapse onto the wrong wing, and the scan fit there
/// stays high, so kidnap detection never fires. The guard asks the correlative matcher for the
/// best place away from the filter's mean that fits nearly as well (the mean's own score, less a
/// margin, as the bar, so most branches are pruned). What the filter does with the answer:
/// - a place that fits at least as well (score_margin): a share of the particles moves there,
///   once per convergence, and the next scans decide between the two;
/// - a place that fits nearly as well (ambiguity_margin): the estimate is reported as ambiguous,
///   its covariance widened to cover that place, while a RivalTest weighs the scans that follow;
///   when they favour the tracked pose the place is set aside (and left out of later searches),
///   when they favour the place a share of the particles moves there.
struct LookAlikeGuardParams {
  /// The filter counts as converged (and is checked) when its particles' spread is below these.
  ConcentrationThresholds converged;
  /// A place moves particles when it scores at least the mean's matcher score minus this
  /// [0..1]. Zero: only places that fit as well or better; a converged filter on the right pose
  /// is then rarely disturbed by a place that fits a little worse.
  double score_margin = 0.0;
  /// A place makes the estimate ambiguous when it scores at least the mean's score minus this
  /// [0..1]; at least score_margin. The wider it is, the more honest the filter's confidence in
  /// repetitive buildings, and the more often a right pose is reported as not yet certain.
  double ambiguity_margin = 0.05;
  /// While converged and no rival is under test, the search is repeated every this many updates
  /// (a look-alike can appear as the robot moves). 0: only at each fresh convergence.
  int recheck_every_updates = 1;
  /// The largest recheck_every_updates accepted: beyond it, 0 (never while converged) says it.
  static constexpr int kMaxRecheckEveryUpdates = 1000;
  /// Look-alikes weighed in one update at most, the one under test included: a look-alike
  /// decided against (by its test ending, or at once on the scan it was found with) is excluded
  /// and the search repeated, so that the estimate is reported unambiguous only when no
  /// look-alike is left (in a corridor many places tie, and the one that lost is seldom the
  /// last). 1: no search in the update where a test ends against its look-alike. At least 1.
  int searches_per_update = 3;
  /// A converged estimate at whose mean fewer than this share of the scan's returns land on
  /// mapped obstacles (ScanFit) is reported unsettled (MclEstimate::scan_unexplained): a scan
  /// that is mostly unmapped things (clutter, people, moved furniture) cannot vouch for a pose,
  /// and a wrong place may explain its few mapped returns as well as the right one. 0: off
  /// [0..1]. In the bench's cluttered office, right estimates ended with 53-89 % of their returns
  /// explained and the confidently wrong one with 63 %; in the clean office, right ones at 72 % or more.
  double min_fit_fraction = 0.7;
  /// Such an estimate's reported spread (and an unverified one's, below) is raised to at least
  /// these, above `converged`'s, so a consumer reading only the covariance sees an unsettled pose
  /// [m], [deg].
  double unexplained_xy_std_m = 1.0;
  double unexplained_phi_std_deg = 20.0;
  /// A converged estimate for which every look-alike search since the filter converged ran out of
  /// max_search_nodes with nothing found is reported unverified (MclEstimate::look_alike_unverified,
  /// its spread widened as above): the guard could not rule out a look-alike, so the pose is not
  /// one to vouch for. The first search that finishes verifies it until the filter spreads out
  /// again. false: an unfinished search counts as finding nothing (the guard before this parameter).
  bool unverified_is_unsettled = true;
  /// When the filter charges see-through beams, the search charges every candidate place its
  /// share of them too (a return from beyond a mapped wall explains nothing), so that places
  /// whose endpoints fit only through walls do not hide the next best one. false: the search
  /// scores endpoints alone, as the guard did before this parameter (the filter and the rival test still
  /// charge them).
  bool search_charges_see_through = true;
  /// A scan whose endpoints fit many places (among racks) leaves many places
  /// to rule out, which can cost seconds: one search scores at most this many nodes and then
  /// takes the best place charged so far (CorrelativeMatcher's max_nodes_scored); when that is
  /// none, the search is unfinished (unverified_is_unsettled). 0: no limit. In the bench's
  /// warehouse a million left a sixth of the searches unfinished, each re-run at the next update;
  /// four million left none, at the same total search CPU (reports/guard_budget).
  long long max_search_nodes = 4000000;
  /// The largest max_search_nodes accepted (days of one core): beyond it, 0 (no limit) says it.
  static constexpr long long kMaxSearchNodesLimit = 1000000000000LL;
  /// One filter update scores at most about this many nodes of look-alike search; a search that
  /// needs more pauses and goes on at the next updates (a place it finds is then moved along the
  /// odometry since its scan and weighed on the current one), the estimate reading unverified
  /// until one finishes. It keeps each tracking update within a bounded time where one search
  /// costs seconds (a warehouse's racks with a long-range scanner), at the price of seeing a
  /// look-alike a few updates later. Only charged searches (search_charges_see_through, with a
  /// filter that charges see-through beams) pause; the others run whole. 0: every search runs to
  /// its end in the update that starts it. At most kMaxSearchNodesLimit.
  long long max_nodes_per_update = 0;
  /// The search tries only headings within this of the four that line the scan's walls up with
  /// the map's (MatchRequest::wall_heading_window_deg), when both have a clear wall direction
  /// [deg]. 0: every heading, the default: at 5 deg the warehouse's tracking CPU fell 1.8x more
  /// than with the relocalizer's window alone, but a trial whose path tells the truth apart was
  /// lost (docs/results.md, "Headings from the walls").
  double wall_heading_window_deg = 0.0;
  RivalTestParams rival_test;  ///< how a look-alike that fits nearly as well is decided
  /// A look-alike found now is also weighed on this many earlier scans, each side moved back
  /// along the odometry to where a twin robot would have stood (ScanHistory): a place that fits
  /// the current stretch of aisle but not the path that led there loses at once. 0: a new
  /// look-alike starts its test even (the guard before this parameter, the default).
  int history_updates = 0;
  /// Rivals decided against are left out of later searches while the filter stays converged; the
  /// oldest is forgotten beyond this many (their odometry-moved positions age).
  int remembered_rejected = 4;
  /// Rivals decided against stay under watch: each scan's evidence keeps adding to their test,
  /// whose lead for the tracked pose is held at rival_test.decisive_log_ratio, and one whose
  /// lead falls to reopen_log_ratio, and that the scan also ranks a look-alike (isLookAlike), is
  /// weighed as a rival again (the estimate turns ambiguous). Two look-alikes can stay alike for
  /// metres and part only later, after the wrong one has won the first scans. The second
  /// condition keeps an old look-alike out when the tracked pose loses for another reason (the
  /// robot was carried off: neither fits, and the search should look for where it went).
  /// false: a rival decided against is only left out of searches.
  bool watch_rejected = true;
  /// [nats], below rival_test.decisive_log_ratio. 0: the scans since the decision have cancelled
  /// the decisive lead it was rejected with.
  double reopen_log_ratio = 0.0;
  double moved_share = 0.5;  ///< share of the particles moved to the look-alike place [0..1]
  double spread_m = 0.1;     ///< std of the moved particles around it, position [m]
  double spread_deg = 3.0;   ///< ... and heading [deg]
};

/// A place other than the tracked one that fits the scan nearly as well.
struct LookAlike {
  mrpt::math::TPose2D pose;
  double score = 0.0;          ///< its LookAlikeGuard::score [0..1]
  double tracked_score = 0.0;  ///< the tracked pose's [0..1]
};

/// What one look-alike search found, and whether it looked everywhere.
struct LookAlikeSearch {
  std::optional<LookAlike> found;
  /// The search ran out of LookAlikeGuardParams::max_search_nodes before it had ruled out every
  /// place: `found` is a true look-alike when set, but when empty a look-alike may still exist.
  bool cut_short = false;
  /// The search paused at its slice's end (LookAlikeGuard::resume): nothing is decided yet.
  bool paused = false;
};

/// A look-alike search that may take several slices (LookAlikeGuardParams::max_nodes_per_update):
/// it keeps its scan's see-through charge and the matcher's search state between them. Its
/// answer is a place for the scan it started on; made by LookAlikeGuard::startSearch.
class LookAlikeSearchInProgress {
 public:
  long long nodesScored() const;  ///< over every slice so far

 private:
  friend class LookAlikeGuard;
  LookAlikeSearchInProgress() = default;
  double tracked_score_ = 0.0;  ///< the tracked pose's score on the search's scan
  /// Owned, so the charge outlives the update whose scan it was read from (a search run whole by
  /// LookAlikeGuard::search uses its caller's instead).
  std::unique_ptr<SeeThroughPenalty::Scan> see_through_;
  std::unique_ptr<CorrelativeMatcher::Search> charged_;  ///< a search that can pause
  LookAlikeSearch uncharged_;                            ///< else the whole search's answer, found at once
};

class LookAlikeGuard {
 public:
  /// Throws std::invalid_argument for a share outside (0, 1], margins or a fit fraction outside
  /// [0, 1], an ambiguity margin below the score margin, an unexplained scan's spread that would
  /// still read as converged, or rival-test settings validateRivalTestParams refuses.
  LookAlikeGuard(std::shared_ptr<const CorrelativeMatcher> matcher, LookAlikeGuardParams params = {});

  /// How well `scan` fits at `pose` in the guard's units: the matcher's endpoint score, less the
  /// share of the returns that see through the map there when `see_through` is given and
  /// search_charges_see_through is on (a return from beyond a mapped wall explains nothing) [0..1].
  double score(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose,
               const SeeThroughPenalty::Scan* see_through = nullptr) const;
  /// The best place at least the matcher's exclusion distance from `pose` (and from each of
  /// `also_excluded`) that scores within ambiguity_margin of it, if any. Scores as score() does:
  /// with `see_through` (and search_charges_see_through), the search charges every candidate its see-through share, so that
  /// places whose endpoints fit only because beams pass through walls do not hide the next best.
  std::optional<LookAlike> lookAlike(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose,
                                     const std::vector<mrpt::math::TPoint2D>& also_excluded = {},
                                     const SeeThroughPenalty::Scan* see_through = nullptr) const {
    return search(scan, pose, also_excluded, see_through).found;
  }
  /// lookAlike(), saying also whether the search ran out of max_search_nodes. Not thread-safe
  /// for one guard (nor is its matcher): each filter thread needs its own.
  LookAlikeSearch search(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose,
                         const std::vector<mrpt::math::TPoint2D>& also_excluded = {},
                         const SeeThroughPenalty::Scan* see_through = nullptr) const;
  /// search(), set up to run in slices by resume() (a search that charges no see-through runs
  /// whole here and resume() hands its answer over). Copies what it needs of its arguments.
  std::unique_ptr<LookAlikeSearchInProgress> startSearch(const mrpt::obs::CObservation2DRangeScan& scan,
                                                         const mrpt::math::TPose2D& pose,
                                                         const std::vector<mrpt::math::TPoint2D>& also_excluded = {},
                                                         const SeeThroughPenalty::Scan* see_through = nullptr) const;
  /// Goes on with `search` for about `max_nodes` more nodes (0: to its end). Paused, or what
  /// search() would have answered on the search's own scan; each slice's score and answer are
  /// those of one search run at once (CorrelativeMatcher::resume).
  LookAlikeSearch resume(LookAlikeSearchInProgress& search, long long max_nodes) const;
  /// It fits at least as well as the tracked pose (by score_margin): particles should move there.
  bool fitsAtLeastAsWell(const LookAlike& place) const {
    return place.score >= place.tracked_score - params_.score_margin;
  }
  /// `place` scores within ambiguity_margin of `tracked` on `scan`, and at least the matcher's
  /// min_score: what lookAlike would report (score()).
  bool isLookAlike(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& place,
                   const mrpt::math::TPose2D& tracked, const SeeThroughPenalty::Scan* see_through = nullptr) const;
  /// Closer than the matcher's exclusion distance: one place, not two.
  bool samePlace(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) const;
  const LookAlikeGuardParams& params() const { return params_; }

 private:
  /// The score a place needs to be a look-alike of a pose scoring `tracked_score`: within
  /// ambiguity_margin of it, and never below what the matcher reports at all.
  double lookAlikeBar(double tracked_score) const;
  /// startSearch(); with own_charge false the search points at `see_through` instead of a copy,
  /// for a search that ends before its caller's charge goes (search()).
  std::unique_ptr<LookAlikeSearchInProgress> beginSearch(const mrpt::obs::CObservation2DRangeScan& scan,
                                                         const mrpt::math::TPose2D& pose,
                                                         const std::vector<mrpt::math::TPoint2D>& also_excluded,
                                                         const SeeThroughPenalty::Scan* see_through,
                                                         bool own_charge) const;
  /// `see_through` where the search charges it (search_charges_see_through), else null.
  const SeeThroughPenalty::Scan* searchCharge(const SeeThroughPenalty::Scan* see_through) const {
    return params_.search_charges_see_through ? see_through : nullptr;
  }

  std::shared_ptr<const CorrelativeMatcher> matcher_;
  LookAlikeGuardParams params_;
};

/// `cov` around `mean`, widened to cover `other` as an equally likely second place: the spread
/// of the two places about the mean (half the outer product of their offset) is added, so a
/// consumer that reads only the covariance sees that the pose is not settled.
mrpt::math::CMatrixDouble33 covarianceWithLookAlike(const mrpt::math::CMatrixDouble33& cov, const mrpt::math::TPose2D& mean,
                                                    const mrpt::math::TPose2D& other);

}  // namespace krp
