// SPDX-License-Identifier: BSD-3-Clause
#include "node_params.h"

#include <XmlRpcValue.h>

#include <cmath>
#include <functional>
#include <map>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/relocalize/confidence_calibration.h"

namespace krp::ros1 {

namespace {

using XmlRpc::XmlRpcValue;

/// The largest look_alike_max_search_nodes accepted: about twenty minutes of one core.
constexpr int kMaxSearchNodes = 1000000000;
/// The most look_alike_rival_refinements accepted: ten halvings take 5 cm to 0.05 mm, far below
/// the map's cells, and each costs another 27 scan evaluations per side and scan.
constexpr int kMaxRivalRefinements = 10;
/// A wall-aligned submap has four turns.
constexpr int kMaxSubmapTurns = 4;
/// More zones than any map is zoned into: searching them all is searching the whole map.
constexpr int kMaxSearchZones = 10000;
// Each stored scan is replayed for every new look-alike: beyond this the replay costs more than a
// second's worth of updates.
constexpr int kMaxHistoryUpdates = 50;

/// One parameter: how to read it from its XML-RPC value into NodeParams.
using Reader = std::function<void(NodeParams&, XmlRpcValue&, const std::string& key)>;

double asNumber(XmlRpcValue& v, const std::string& key) {
  if (v.getType() == XmlRpcValue::TypeDouble) return static_cast<double>(v);
  if (v.getType() == XmlRpcValue::TypeInt) return static_cast<int>(v);
  throw InputError("parameter '" + key + "'", "must be a number");
}

Reader string(std::string NodeParams::*field) {
  return [field](NodeParams& p, XmlRpcValue& v, const std::string& key) {
    if (v.getType() != XmlRpcValue::TypeString) throw InputError("parameter '" + key + "'", "must be a string");
    p.*field = static_cast<std::string>(v);
  };
}

Reader boolean(bool NodeParams::*field) {
  return [field](NodeParams& p, XmlRpcValue& v, const std::string& key) {
    if (v.getType() != XmlRpcValue::TypeBoolean) throw InputError("parameter '" + key + "'", "must be true or false");
    p.*field = static_cast<bool>(v);
  };
}

Reader number(double NodeParams::*field, double min, double max) {
  return [=](NodeParams& p, XmlRpcValue& v, const std::string& key) {
    const double x = asNumber(v, key);
    if (!std::isfinite(x) || x < min || x > max)
      throw InputError("parameter '" + key + "'",
                       "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + std::to_string(x));
    p.*field = x;
  };
}

Reader integer(int NodeParams::*field, int min, int max) {
  return [=](NodeParams& p, XmlRpcValue& v, const std::string& key) {
    if (v.getType() != XmlRpcValue::TypeInt) throw InputError("parameter '" + key + "'", "must be an integer");
    const int x = static_cast<int>(v);
    if (x < min || x > max)
      throw InputError("parameter '" + key + "'",
                       "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + std::to_string(x));
    p.*field = x;
  };
}

const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> r = {
      {"map_file", string(&NodeParams::map_file)},
      {"global_frame", string(&NodeParams::global_frame)},
      {"odom_frame", string(&NodeParams::odom_frame)},
      {"base_frame", string(&NodeParams::base_frame)},
      {"transform_timeout_s", number(&NodeParams::transform_timeout_s, 0.0, 10.0)},
      {"min_valid_returns", integer(&NodeParams::min_valid_returns, 1, 100000)},
      {"backend", string(&NodeParams::backend)},
      {"models_dir", string(&NodeParams::models_dir)},
      {"zones_file", string(&NodeParams::zones_file)},
      {"calibration_file", string(&NodeParams::calibration_file)},
      {"min_localized_fit_fraction", number(&NodeParams::min_localized_fit_fraction, 0.0, 1.0)},
      {"cross_check", boolean(&NodeParams::cross_check)},
      {"top_turns", integer(&NodeParams::top_turns, 1, kMaxSubmapTurns)},
      {"stop_turns_once_localized", boolean(&NodeParams::stop_turns_once_localized)},
      {"search_zones", integer(&NodeParams::search_zones, 0, kMaxSearchZones)},
      {"wall_heading_window_deg",
       number(&NodeParams::wall_heading_window_deg, 0.0, MatchRequest::kMaxWallHeadingWindowDeg)},
      {"relocalize_on_startup", boolean(&NodeParams::relocalize_on_startup)},
      {"relocalize_on_kidnap", boolean(&NodeParams::relocalize_on_kidnap)},
      {"publish_when_not_localized", boolean(&NodeParams::publish_when_not_localized)},
      {"max_scan_age_s", number(&NodeParams::max_scan_age_s, 0.0, 3600.0)},
      {"trigger_timeout_s", number(&NodeParams::trigger_timeout_s, 0.1, 600.0)},
      {"mode", string(&NodeParams::mode)},
      {"transform_tolerance_s", number(&NodeParams::transform_tolerance_s, 0.0, 10.0)},
      {"update_min_d", number(&NodeParams::update_min_d, 0.0, 100.0)},
      {"update_min_a", number(&NodeParams::update_min_a, 0.0, 2 * M_PI)},
      {"max_particles", integer(&NodeParams::max_particles, 100, 1000000)},
      {"uniform_fraction", number(&NodeParams::uniform_fraction, 0.0, 0.99)},
      {"shrink_uniform_start", boolean(&NodeParams::shrink_uniform_start)},
      {"look_alike_guard", boolean(&NodeParams::look_alike_guard)},
      {"look_alike_ambiguity_margin", number(&NodeParams::look_alike_ambiguity_margin, 0.0, 1.0)},
      {"look_alike_min_fit_fraction", number(&NodeParams::look_alike_min_fit_fraction, 0.0, 1.0)},
      {"look_alike_watch_rejected", boolean(&NodeParams::look_alike_watch_rejected)},
      {"look_alike_unverified_is_unsettled", boolean(&NodeParams::look_alike_unverified_is_unsettled)},
      {"see_through_penalty", boolean(&NodeParams::see_through_penalty)},
      {"look_alike_search_charges_see_through", boolean(&NodeParams::look_alike_search_charges_see_through)},
      {"look_alike_refit_charges_see_through", boolean(&NodeParams::look_alike_refit_charges_see_through)},
      {"look_alike_rival_refinements", integer(&NodeParams::look_alike_rival_refinements, 0, kMaxRivalRefinements)},
      {"look_alike_max_search_nodes", integer(&NodeParams::look_alike_max_search_nodes, 0, kMaxSearchNodes)},
      {"look_alike_max_nodes_per_update", integer(&NodeParams::look_alike_max_nodes_per_update, 0, kMaxSearchNodes)},
      {"look_alike_history_updates", integer(&NodeParams::look_alike_history_updates, 0, kMaxHistoryUpdates)},
      {"look_alike_recheck_every_updates", integer(&NodeParams::look_alike_recheck_every_updates, 0,
                                                           LookAlikeGuardParams::kMaxRecheckEveryUpdates)},
  };
  return r;
}

}  // namespace

std::vector<std::string> nodeParamNames() {
  std::vector<std::string> names;
  for (const auto& [name, reader] : readers()) names.push_back(name);
  return names;
}

NodeParams loadNodeParams(const ros::NodeHandle& private_nh) {
  NodeParams p;
  XmlRpcValue all;
  // No private parameters at all is fine: every key has a default.
  if (!private_nh.getParam(private_nh.getNamespace(), all)) return p;
  if (all.getType() != XmlRpcValue::TypeStruct)
    throw InputError("parameters of " + private_nh.getNamespace(), "expected a dictionary of parameters");
  for (auto it = all.begin(); it != all.end(); ++it) {
    const auto reader = readers().find(it->first);
    if (reader == readers().end()) {
      std::string known;
      for (const auto& n : nodeParamNames()) known += (known.empty() ? "" : ", ") + n;
      throw InputError("parameter '" + it->first + "'", "unknown (known: " + known + ")");
    }
    reader->second(p, it->second, it->first);
  }
  if (p.mode != "relocalize" && p.mode != "track")
    throw InputError("parameter 'mode'", "must be 'relocalize' or 'track', got '" + p.mode + "'");
  bool known_backend = false;
  for (const auto& b : hypothesisSourceBackends()) known_backend |= b == p.backend;
  if (!known_backend) throw InputError("parameter 'backend'", "unknown backend '" + p.backend + "'");
  if (p.backend == "learned" && p.models_dir.empty())
    throw InputError("parameter 'models_dir'", "backend 'learned' needs the map's models folder");
  return p;
}

HypothesisSourceParams NodeParams::hypothesisSource() const {
  HypothesisSourceParams h;
  h.backend = backend;
  h.models_dir = models_dir;
  h.zones_file = zones_file;
  h.learned.cross_check.enabled = cross_check;
  h.learned.top_turns = top_turns;
  h.learned.stop_turns_once_localized = stop_turns_once_localized;
  h.learned.zone_search.zones = search_zones;
  h.learned.wall_heading_window_deg = wall_heading_window_deg;
  useMinLocalizedFitFraction(min_localized_fit_fraction, h.learned, h.matcher);
  if (!calibration_file.empty()) useConfidenceCalibration(readConfidenceCalibration(calibration_file), h.learned, h.matcher);
  return h;
}

SeededInitParams NodeParams::seeded() const {
  SeededInitParams s;
  s.max_particles = static_cast<std::size_t>(max_particles);
  s.min_particles = std::min(s.min_particles, s.max_particles);
  s.uniform_fraction = uniform_fraction;
  if (!shrink_uniform_start) s.fallback_shrinks.reset();
  return s;
}

OdometryTrackerParams NodeParams::tracker() const {
  OdometryTrackerParams t;
  t.update_min_d_m = update_min_d;
  t.update_min_a_deg = update_min_a * 180.0 / M_PI;
  return t;
}

KidnapDetectorParams NodeParams::kidnap() const {
  KidnapDetectorParams k;
  k.enabled = relocalize_on_kidnap;
  return k;
}

MclParams NodeParams::mcl() const {
  MclParams m;
  m.kidnap = kidnap();
  m.see_through.enabled = see_through_penalty;
  return m;
}

LookAlikeGuardParams NodeParams::lookAlikeGuard() const {
  LookAlikeGuardParams g;
  g.ambiguity_margin = look_alike_ambiguity_margin;
  g.min_fit_fraction = look_alike_min_fit_fraction;
  g.watch_rejected = look_alike_watch_rejected;
  g.unverified_is_unsettled = look_alike_unverified_is_unsettled;
  g.search_charges_see_through = look_alike_search_charges_see_through;
  g.rival_test.refit_charges_see_through = look_alike_refit_charges_see_through;
  g.rival_test.finer_refinements = look_alike_rival_refinements;
  g.max_search_nodes = look_alike_max_search_nodes;
  g.max_nodes_per_update = look_alike_max_nodes_per_update;
  g.history_updates = look_alike_history_updates;
  g.recheck_every_updates = look_alike_recheck_every_updates;
  return g;
}

}  // namespace krp::ros1
