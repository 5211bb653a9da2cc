// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include <ros/node_handle.h>

#include "mrpt_krp_plugin/filter/kidnap_detector.h"
#include "mrpt_krp_plugin/filter/look_alike_guard.h"
#include "mrpt_krp_plugin/filter/odometry_tracker.h"
#include "mrpt_krp_plugin/filter/seeded_initializer.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_source.h"

namespace krp::ros1 {

/// Every parameter of krp_relocalizer_node (private namespace), with its default. The
/// documented list is config/krp_relocalizer.yaml; the two must agree (a test checks it).
struct NodeParams {
  // --- inputs
  std::string map_file;           ///< a map file (.yaml, .gridmap, .bt); empty: subscribe to `map`
  std::string global_frame = "map";
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  double transform_timeout_s = 0.1;  ///< how long a scan waits for its odom -> base transform [s]
  int min_valid_returns = 10;        ///< a scan with fewer usable returns is rejected

  // --- relocalization
  std::string backend = "global-matcher";  ///< `learned` (needs models_dir) or `global-matcher`
  std::string models_dir;                  ///< the models of this map (krp-train-map's output)
  std::string zones_file;                  ///< `learned`: their zones.yaml, enables the zone search (optional)
  std::string calibration_file;            ///< the map's confidence calibration (krp-bench --fit-calibration; optional)
  /// A relocalization whose best pose explains fewer of the scan's returns than this is "not
  /// localized" (HypothesisRankingParams::min_localized_fit_fraction; 0 = off) [0..1]
  double min_localized_fit_fraction = HypothesisRankingParams{}.min_localized_fit_fraction;
  bool cross_check = true;                 ///< `learned`: check the best answer for look-alike places (CrossCheckParams)
  /// `learned`, wall-aligned models: submap turns the keypoint model runs on, the classifier's
  /// surest first (RelocalizerParams::top_turns)
  int top_turns = RelocalizerParams{}.top_turns;
  /// `learned`: with the cross-check, the next turn runs only while no turn so far gave a
  /// credible answer (RelocalizerParams::stop_turns_once_localized)
  bool stop_turns_once_localized = RelocalizerParams{}.stop_turns_once_localized;
  /// `learned`, with zones: the classifier's most likely zones the correlative matcher searches
  /// when the keypoints give no credible pose (ZoneSearchParams::zones; 0 = no zone search)
  int search_zones = ZoneSearchParams{}.zones;
  /// `learned`: the zone search and the cross-check try only headings within this of the four
  /// that line the scan's walls up with the map's, when both have a clear wall direction
  /// (RelocalizerParams::wall_heading_window_deg; 0 = every heading) [deg]
  double wall_heading_window_deg = RelocalizerParams{}.wall_heading_window_deg;
  bool relocalize_on_startup = true;       ///< relocalize from the first scan
  bool relocalize_on_kidnap = false;       ///< relocalize when the tracked pose stops fitting the scans
  bool publish_when_not_localized = false;  ///< publish `initialpose` even when the relocalizer is unsure
  double max_scan_age_s = 1.0;      ///< a scan older than this is not relocalized from [s]
  double trigger_timeout_s = 10.0;  ///< how long `~relocalize` waits for the answer [s]

  // --- modes
  std::string mode = "relocalize";  ///< `relocalize` (beside AMCL) or `track` (runs the filter itself)
  double transform_tolerance_s = 0.1;  ///< `track`: map -> odom is future-dated by this [s]
  double update_min_d = 0.2;           ///< `track`: filter update after this much motion [m]
  double update_min_a = 0.5236;        ///< `track`: or this much turn [rad]
  int max_particles = 5000;            ///< `track`: cap of the seeded particle cloud
  double uniform_fraction = 0.05;      ///< `track`: share of particles spread uniformly [0..1)
  /// `track`: a filter that started uniform (the relocalizer had nothing credible) sizes its set
  /// by KLD sampling once it has converged, down to a seeded start's floor, instead of tracking
  /// with the tens of thousands of particles that cover the map (SeededInitParams::fallback_shrinks)
  bool shrink_uniform_start = SeededInitParams{}.fallback_shrinks.has_value();
  bool look_alike_guard = true;        ///< `track`: check the converged filter for a look-alike place (LookAlikeGuard)
  /// `track`: a look-alike scoring within this of the tracked pose makes it ambiguous [0..1]
  double look_alike_ambiguity_margin = LookAlikeGuardParams{}.ambiguity_margin;
  /// `track`: a converged pose explaining fewer of the scan's returns than this is published
  /// with a widened covariance and a warning (0 = off) [0..1]
  double look_alike_min_fit_fraction = LookAlikeGuardParams{}.min_fit_fraction;
  /// `track`: a look-alike the scans decided against stays under watch and is weighed again when
  /// later scans undo its defeat (LookAlikeGuardParams::watch_rejected)
  bool look_alike_watch_rejected = LookAlikeGuardParams{}.watch_rejected;
  /// `track`: returns from beyond a mapped obstacle count against a particle (SeeThroughParams)
  bool see_through_penalty = SeeThroughParams{}.enabled;
  /// `track`: the look-alike search charges each place for the returns it would see through
  /// (with see_through_penalty; LookAlikeGuardParams::search_charges_see_through)
  bool look_alike_search_charges_see_through = LookAlikeGuardParams{}.search_charges_see_through;
  /// `track`: the rival test re-fits the pose and its look-alike to each scan with the see-through
  /// charge in the fit (with see_through_penalty; RivalTestParams::refit_charges_see_through)
  bool look_alike_refit_charges_see_through = RivalTestParams{}.refit_charges_see_through;
  /// `track`: finer grids, each of half the last one's steps, on which the rival test re-fits
  /// each side after its 5 cm / 1 deg grid (0 = that grid only; RivalTestParams::finer_refinements)
  int look_alike_rival_refinements = RivalTestParams{}.finer_refinements;
  /// `track`: nodes one charged look-alike search may score before it answers with the best place
  /// charged so far (0 = no limit; LookAlikeGuardParams::max_search_nodes)
  int look_alike_max_search_nodes = static_cast<int>(LookAlikeGuardParams{}.max_search_nodes);
  /// `track`: nodes of look-alike search one filter update may score; a charged search that needs
  /// more pauses and goes on at the next updates, the pose published as unverified meanwhile, so
  /// that no update stalls the tracking on a large map (0 = each search runs to its end at once;
  /// LookAlikeGuardParams::max_nodes_per_update). The node's default differs from the library's:
  /// a live robot must keep up with its scans, a log replayed offline need not.
  int look_alike_max_nodes_per_update = kNodeMaxNodesPerUpdate;
  static constexpr int kNodeMaxNodesPerUpdate = 500000;
  /// `track`: a converged pose whose look-alike searches all ran out of that budget with nothing
  /// found is published with a widened covariance (LookAlikeGuardParams::unverified_is_unsettled)
  bool look_alike_unverified_is_unsettled = LookAlikeGuardParams{}.unverified_is_unsettled;
  /// `track`: while the filter stays converged, the look-alike search runs again every this many
  /// filter updates (0 = only when it converges afresh; LookAlikeGuardParams::recheck_every_updates)
  int look_alike_recheck_every_updates = LookAlikeGuardParams{}.recheck_every_updates;
  /// `track`: a look-alike found is also weighed on this many earlier scans, each side moved back
  /// along the odometry (0 = off, the default; LookAlikeGuardParams::history_updates)
  int look_alike_history_updates = LookAlikeGuardParams{}.history_updates;

  // Derived library parameters.
  HypothesisSourceParams hypothesisSource() const;
  SeededInitParams seeded() const;
  OdometryTrackerParams tracker() const;
  KidnapDetectorParams kidnap() const;
  MclParams mcl() const;
  LookAlikeGuardParams lookAlikeGuard() const;
};

/// Reads the private parameters. InputError naming the key for an unknown key (a typo would
/// otherwise silently keep a default), a value of the wrong type, or a value out of range.
NodeParams loadNodeParams(const ros::NodeHandle& private_nh);

/// The names of all parameters, for the documentation check.
std::vector<std::string> nodeParamNames();

}  // namespace krp::ros1
