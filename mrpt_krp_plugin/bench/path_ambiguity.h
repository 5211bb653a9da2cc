// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <memory>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/bench/place_tracker.h"
#include "mrpt_krp_plugin/filter/rival_test.h"
#include "mrpt_krp_plugin/filter/see_through.h"
#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"

namespace krp {

/// How hard a trial is for any method that reads the map, known only to the bench, which holds
/// the truth: in a hall of repeated aisles the robot's whole path may fit another aisle as well
/// as its own, and then no method can tell where it is, however it is built.
struct PathAmbiguityParams {
  /// Places that fit the trial's first scan within this of the truth's own matcher score are
  /// weighed [matcher score, 0..1]. A place further below has lost on that scan alone by more
  /// than the decisive ratio (a tenth of a 180-return scan is ~18 returns at ~3 nats each).
  double first_scan_margin = 0.1;
  /// At most this many such places (the matcher's best ones, each at least its exclusion_m from
  /// the truth and from one another). 0: only the places where the methods ended (EndPlace).
  int max_places = 8;
  /// How the truth and each place are placed on the first scan, moved along the path and
  /// re-fitted to every scan with the filter's sensor model and its see-through penalty in the
  /// fit (PlaceTracker).
  PlaceTrackerParams tracking;
  /// The truth's lead over every place, summed over the path, that tells it apart (and a
  /// place's lead that makes the trial misleading): the look-alike guard's bar [nats].
  double decisive_log_ratio = RivalTestParams{}.decisive_log_ratio;
  /// The truth is weighed as the places are (`tracking`), started this share of a refine step off the exact pose in x, y
  /// and heading: a place found on the matcher's grid is never exactly on its own true
  /// equivalent, and a quarter step is the mean error of a pose rounded to the grid. Weighed at
  /// its exact pose instead, the truth gained a few nats a scan on every place (in the
  /// warehouse, exact translated copies of an aisle lost by 45 nats over 10 scans) [0..0.5].
  double truth_offset_steps = 0.25;
};

/// Throws std::invalid_argument for a margin outside [0, 1], fewer than one place, tracking
/// settings validatePlaceTrackerParams refuses, a decisive ratio that is not positive or a truth
/// offset outside [0, 0.5].
void validatePathAmbiguityParams(const PathAmbiguityParams& params);

enum class PathVerdict {
  not_checked,  ///< no check asked for, or a trial it does not apply to (a kidnap)
  told_apart,   ///< every place near as good on the first scan loses decisively over the path
  ambiguous,    ///< a place elsewhere explains the whole path within the decisive ratio
  misleading,   ///< a place elsewhere explains the path decisively better than the truth
};
std::string toString(PathVerdict verdict);

/// Where a method's filter ended a trial away from the truth. The first scan alone can offer
/// the wrong places: where a short view along an aisle fits dozens of spots equally, they fill
/// the matcher's list, and a place that fits every later scan as the truth does is never
/// weighed (the warehouse's trial 15, the office's lds01 trial 94). A place a method settled on
/// has fitted the whole path well by construction, so it is the one the verdict must weigh.
struct EndPlace {
  std::string source;          ///< the method that ended there
  mrpt::math::TPose2D pose;    ///< its estimate at the trial's last scan
};

struct PathAmbiguity {
  PathVerdict verdict = PathVerdict::not_checked;
  int places = 0;      ///< places weighed: those the first scan offered, then the end places
  int end_places = 0;  ///< of them, the places where methods ended (EndPlace, after removing repeats)
  /// The truth's lead over the place that came closest, summed over the path [nats]; +inf
  /// when the first scan offered none.
  double closest_log_ratio = 0.0;
  double closest_distance_m = -1.0;  ///< that place's start from the truth's [m]; -1 without one
  /// Where that place came from: "first_scan", or the EndPlace's source; empty without one.
  std::string closest_source;
};

/// Each place that fits a trial's first scan nearly as well as the truth, and each place where
/// a method ended (moved back to where a twin robot would have had to start), is moved along
/// the truth's own path (rigidly, as a twin robot would drive it) and weighed against the
/// truth, moved and re-fitted the same way, over every scan of the trial.
class PathAmbiguityCheck {
 public:
  /// `map` carries the filter's sensor model (SensorModelMap::grid); `see_through`, when not
  /// null, charges each side as the guarded filter does. Throws as validatePathAmbiguityParams.
  PathAmbiguityCheck(std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map,
                     std::shared_ptr<const CorrelativeMatcher> matcher,
                     std::shared_ptr<const SeeThroughPenalty> see_through, PathAmbiguityParams params = {});

  /// `truth[i]` is where `scans[i]` was taken; `ends` are where methods ended at the last scan
  /// (one within the matcher's exclusion_m of the truth or of a place already weighed, at the
  /// start, is the same place and is not weighed again). Throws std::invalid_argument when
  /// truth and scans differ in length or are empty.
  PathAmbiguity check(const std::vector<mrpt::math::TPose2D>& truth,
                      const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans,
                      const std::vector<EndPlace>& ends = {}) const;

 private:
  std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> map_;
  std::shared_ptr<const CorrelativeMatcher> matcher_;
  std::shared_ptr<const SeeThroughPenalty> see_through_;
  PathAmbiguityParams params_;
};

}  // namespace krp
