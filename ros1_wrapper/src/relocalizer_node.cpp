// SPDX-License-Identifier: BSD-3-Clause
#include "relocalizer_node.h"

#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/TransformStamped.h>
#include <std_msgs/String.h>
#include <tf2/exceptions.h>
#include <visualization_msgs/MarkerArray.h>

#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/filter/look_alike_guard.h"
#include "mrpt_krp_plugin/map/map_loader.h"
#include "guard_cost_note.h"
#include "ros_conversions.h"

namespace krp::ros1 {

namespace {
// Published topics keep this many messages for slow subscribers.
constexpr int kPublisherQueue = 5;
// A slow callback drops all but the newest scans: stale scans are worth nothing here.
constexpr int kScanQueue = 1;
constexpr double kProblemLogPeriodS = 5.0;

ros::Time fromNs(uint64_t ns) {
  ros::Time t;
  t.fromNSec(ns);
  return t;
}

std::string describe(const PoseHypothesis& h, const OccupancyMap& map) {
  const auto p = map.toSourceFrame(h.pose);
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << "x=" << p.x << " y=" << p.y << " yaw_deg=" << p.phi * 180.0 / M_PI << " confidence=" << h.confidence
    << " fit=" << h.fit_fraction;
  return s.str();
}
}  // namespace

RelocalizerNode::RelocalizerNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : params_(loadNodeParams(private_nh)), nh_(nh), pnh_(private_nh), tf_listener_(tf_buffer_), kidnap_(params_.kidnap()) {
  initialpose_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("initialpose", kPublisherQueue);
  hypotheses_pub_ = pnh_.advertise<geometry_msgs::PoseArray>("hypotheses", kPublisherQueue, true);
  markers_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("hypothesis_markers", kPublisherQueue, true);
  status_pub_ = pnh_.advertise<std_msgs::String>("status", kPublisherQueue, true);
  relocalization_pending_ = params_.relocalize_on_startup;
  if (params_.mode == "track") {
    amcl_pose_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", kPublisherQueue, true);
    cloud_pub_ = nh_.advertise<geometry_msgs::PoseArray>("particlecloud", kPublisherQueue, true);
    track_worker_ = std::make_unique<LatestOnlyWorker<TrackJob>>([this](TrackJob& job) { track(job); },
                                                                 [](TrackJob&) {});
  }

  if (!params_.map_file.empty()) useMap(loadOccupancyMap(params_.map_file));
  else map_sub_ = nh_.subscribe("map", 1, &RelocalizerNode::onMap, this);
  scan_sub_ = nh_.subscribe("scan", kScanQueue, &RelocalizerNode::onScan, this);
  if (params_.mode == "relocalize" && params_.relocalize_on_kidnap)
    amcl_pose_sub_ = nh_.subscribe("amcl_pose", 1, &RelocalizerNode::onAmclPose, this);
  if (params_.mode == "track") initialpose_sub_ = nh_.subscribe("initialpose", 1, &RelocalizerNode::onInitialPose, this);
  global_localization_srv_ =
      nh_.advertiseService("global_localization", &RelocalizerNode::onGlobalLocalization, this);
  relocalize_srv_ = pnh_.advertiseService("relocalize", &RelocalizerNode::onRelocalize, this);
  reload_srv_ = pnh_.advertiseService("reload", &RelocalizerNode::onReload, this);
  report("started: mode " + params_.mode + ", backend " + params_.backend +
             (params_.map_file.empty() ? ", waiting for `map`" : ", map " + params_.map_file),
         false);
}

RelocalizerNode::~RelocalizerNode() {
  scan_sub_.shutdown();
  map_sub_.shutdown();
  amcl_pose_sub_.shutdown();
  initialpose_sub_.shutdown();
  global_localization_srv_.shutdown();
  relocalize_srv_.shutdown();
  reload_srv_.shutdown();
  // The workers call back into this object: stop them before anything else goes.
  track_worker_.reset();
  std::shared_ptr<MapState> state;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state.swap(map_state_);
  }
  state.reset();
}

void RelocalizerNode::useMap(OccupancyMap map) {
  auto state = std::make_shared<MapState>();
  state->map = std::make_shared<const OccupancyMap>(std::move(map));
  const std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> grid = state->map->grid;
  std::string backend, warning;
  const HypothesisSource raw = makeHypothesisSource(grid, params_.hypothesisSource(), &backend, &warning);
  // The relocalizer and the tracker's initializer share one source: one call at a time.
  auto source_mutex = std::make_shared<std::mutex>();
  const HypothesisSource serialized = [raw, source_mutex](const mrpt::obs::CObservation2DRangeScan& scan) {
    std::lock_guard<std::mutex> lock(*source_mutex);
    return raw(scan);
  };
  const auto map_ptr = state->map;
  state->relocalizer = std::make_unique<AsyncRelocalizer>(
      serialized, [this, map_ptr](const RelocalizationReply& reply) { onReply(reply, map_ptr); });
  if (params_.mode == "relocalize" && params_.relocalize_on_kidnap) state->fit = std::make_unique<ScanFitScorer>(*grid);
  if (params_.mode == "track") {
    state->user_pose = std::make_shared<std::optional<Ranking>>();
    state->user_pose_mutex = std::make_shared<std::mutex>();
    // A pose given by a user seeds the filter once, instead of the relocalizer.
    const auto user_pose = state->user_pose;
    const auto user_pose_mutex = state->user_pose_mutex;
    const HypothesisSource seeding_source = [serialized, user_pose, user_pose_mutex](
                                                const mrpt::obs::CObservation2DRangeScan& scan) {
      {
        std::lock_guard<std::mutex> lock(*user_pose_mutex);
        if (*user_pose) {
          Ranking given = **user_pose;
          user_pose->reset();
          return given;
        }
      }
      return serialized(scan);
    };
    state->seeding = std::make_shared<SeededInitializer>(seeding_source, params_.seeded());
    // Each seeding draws its uniform share from these instead of reading the map's cells again.
    state->seeding->useFreeCells(std::make_shared<const FreeCells>(*grid, params_.seeded().free_cell_min_freeness));
    state->tracker = std::make_shared<OdometryTracker>(grid, state->seeding, params_.mcl(), params_.tracker());
    if (params_.look_alike_guard)
      state->tracker->setLookAlikeGuard(std::make_shared<LookAlikeGuard>(std::make_shared<CorrelativeMatcher>(*grid),
                                                                                params_.lookAlikeGuard()));
  }
  std::ostringstream s;
  s << "map in use: " << state->map->source << " (" << grid->getSizeX() << " x " << grid->getSizeY()
    << " cells); backend " << backend;
  if (!warning.empty()) s << "; " << warning << " (zones_file)";
  {
    std::lock_guard<std::mutex> lock(mutex_);
    map_state_ = state;
    map_to_odom_.reset();
    kidnap_.reset();
    // A new map invalidates any pose: find it again on it.
    relocalization_pending_ = relocalization_pending_ || params_.relocalize_on_startup;
  }
  report(s.str(), !warning.empty());
}

std::shared_ptr<RelocalizerNode::MapState> RelocalizerNode::mapState() {
  std::lock_guard<std::mutex> lock(mutex_);
  return map_state_;
}

void RelocalizerNode::onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
  try {
    useMap(occupancyMapFromRos(*msg));
  } catch (const std::exception& e) {
    report(std::string("map rejected, keeping the previous one: ") + e.what(), true);
  }
}

void RelocalizerNode::onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
  const std::shared_ptr<MapState> state = mapState();
  if (!state) {
    report("scan ignored: no map yet", true);
    return;
  }
  mrpt::poses::CPose3D laser_in_base;
  mrpt::math::TPose2D odom;
  try {
    const auto laser = tf_buffer_.lookupTransform(params_.base_frame, msg->header.frame_id, ros::Time(0));
    const auto p = pose2DFromRos(laser.transform);
    laser_in_base = mrpt::poses::CPose3D(p.x, p.y, laser.transform.translation.z, p.phi, 0, 0);
    const auto base = tf_buffer_.lookupTransform(params_.odom_frame, params_.base_frame, msg->header.stamp,
                                                 ros::Duration(params_.transform_timeout_s));
    odom = pose2DFromRos(base.transform);
  } catch (const tf2::TransformException& e) {
    report(std::string("scan ignored: no transform: ") + e.what(), true);
    return;
  }
  mrpt::obs::CObservation2DRangeScan::Ptr scan;
  try {
    scan = scanFromRos(*msg, laser_in_base, ScanCheck{params_.min_valid_returns});
  } catch (const InputError& e) {
    report(std::string("scan ignored: ") + e.what(), true);
    return;
  }
  RelocalizationRequest request{scan, msg->header.stamp.toNSec(), odom};
  bool relocalize_now = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = request;
    relocalize_now = relocalization_pending_ && params_.mode == "relocalize";
    relocalization_pending_ = relocalization_pending_ && !relocalize_now;
    if (params_.mode == "track" && relocalization_pending_) {
      reinitialize_tracker_ = true;
      relocalization_pending_ = false;
    }
  }
  if (relocalize_now) state->relocalizer->submit(request);
  if (params_.mode == "relocalize" && state->fit) checkKidnap(*scan, msg->header.stamp);
  if (params_.mode == "track") {
    track_worker_->submit(TrackJob{scan, odom, msg->header.stamp, state});
    broadcastMapToOdom(msg->header.stamp);
  }
}

void RelocalizerNode::onAmclPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!map_state_) return;
  amcl_pose_ = map_state_->map->toGridFrame(pose2DFromRos(msg->pose.pose));
  amcl_pose_stamp_ = msg->header.stamp;
}

void RelocalizerNode::onInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
  const std::shared_ptr<MapState> state = mapState();
  if (!state) {
    report("initialpose ignored: no map yet", true);
    return;
  }
  if (!msg->header.frame_id.empty() && msg->header.frame_id != params_.global_frame) {
    report("initialpose ignored: frame '" + msg->header.frame_id + "' is not '" + params_.global_frame + "'", true);
    return;
  }
  PoseHypothesis h;
  h.pose = state->map->toGridFrame(pose2DFromRos(msg->pose.pose));
  h.cov = covarianceFromRos(msg->pose.covariance, state->map->yaw_rad);
  h.confidence = 1.0;
  Ranking given;
  given.hypotheses = {h};
  given.localized = true;
  {
    std::lock_guard<std::mutex> lock(*state->user_pose_mutex);
    *state->user_pose = given;
  }
  reinitialize_tracker_ = true;
  report("initialpose received: the filter re-seeds around it at the next scan", false);
}

void RelocalizerNode::checkKidnap(const mrpt::obs::CObservation2DRangeScan& scan, const ros::Time& stamp) {
  std::shared_ptr<MapState> state;
  std::optional<mrpt::math::TPose2D> pose;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state = map_state_;
    if (amcl_pose_ && std::abs((stamp - amcl_pose_stamp_).toSec()) <= params_.max_scan_age_s) pose = amcl_pose_;
  }
  if (!pose || !state || !state->fit) return;
  const double fit = state->fit->score(scan, *pose).fit_fraction;
  bool kidnapped = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    kidnapped = kidnap_.update(fit);
  }
  if (!kidnapped) return;
  std::ostringstream s;
  s << "kidnap suspected: only " << fit << " of the scan fits the map at amcl_pose; relocalizing";
  report(s.str(), true);
  std::string why;
  relocalizeLatest(&why);
}

std::optional<std::shared_future<RelocalizationReply>> RelocalizerNode::relocalizeLatest(std::string* why_not) {
  std::shared_ptr<MapState> state;
  RelocalizationRequest request;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!map_state_) {
      *why_not = "no map yet";
      return std::nullopt;
    }
    if (!latest_) {
      *why_not = "no usable scan yet";
      return std::nullopt;
    }
    const double age = (ros::Time::now() - fromNs(latest_->stamp_ns)).toSec();
    if (age > params_.max_scan_age_s) {
      std::ostringstream s;
      s << "the newest usable scan is " << age << " s old (max_scan_age_s " << params_.max_scan_age_s << ")";
      *why_not = s.str();
      return std::nullopt;
    }
    state = map_state_;
    request = *latest_;
  }
  return state->relocalizer->submit(request);
}

void RelocalizerNode::onReply(const RelocalizationReply& reply, const std::shared_ptr<const OccupancyMap>& map) {
  if (reply.dropped) return;
  if (!reply.error.empty()) {
    report("relocalization failed: " + reply.error, true);
    return;
  }
  const ros::Time stamp = fromNs(reply.request.stamp_ns);
  publishHypotheses(reply.ranking, *map, stamp);
  std::ostringstream s;
  s.precision(0);
  s << std::fixed;
  if (params_.mode == "track") {
    // The node's own filter is the consumer: `~relocalize` re-seeds it instead.
    s << (reply.ranking.localized ? "localized: " + describe(reply.ranking.hypotheses.front(), *map)
                                  : "not localized: " + reply.ranking.reason)
      << " (backend " << params_.backend << ", " << reply.latency_ms << " ms)";
    report(s.str(), !reply.ranking.localized);
  } else if (reply.ranking.localized ||
             (params_.publish_when_not_localized && !reply.ranking.hypotheses.empty())) {
    std_msgs::Header header;
    header.stamp = stamp;
    header.frame_id = params_.global_frame;
    initialpose_pub_.publish(initialPoseMsg(reply.ranking.hypotheses.front(), *map, header));
    s << (reply.ranking.localized ? "localized: " : "published although not localized: ")
      << describe(reply.ranking.hypotheses.front(), *map) << " (backend " << params_.backend << ", "
      << reply.latency_ms << " ms)";
    report(s.str(), !reply.ranking.localized);
  } else {
    s << "not localized: " << reply.ranking.reason << " (" << reply.ranking.hypotheses.size()
      << " hypotheses, backend " << params_.backend << ", " << reply.latency_ms << " ms); initialpose not published";
    report(s.str(), true);
  }
}

bool RelocalizerNode::onGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  if (params_.mode == "track") {
    reinitialize_tracker_ = true;
    report("global_localization: the filter re-seeds from the next scan", false);
    return true;
  }
  std::string why;
  if (!relocalizeLatest(&why)) {
    std::lock_guard<std::mutex> lock(mutex_);
    relocalization_pending_ = true;
    last_problem_.clear();
  }
  report(why.empty() ? "global_localization: relocalizing from the newest scan"
                     : "global_localization: " + why + "; will relocalize from the next scan",
         false);
  return true;
}

bool RelocalizerNode::onReload(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  const auto state = mapState();
  if (!state) {
    res.success = false;
    res.message = "not reloaded: no map yet";
  } else {
    try {
      useMap(*state->map);
      res.success = true;
      res.message = "reloaded: backend " + params_.backend;
    } catch (const std::exception& e) {
      res.success = false;
      res.message = std::string("not reloaded, keeping the loaded backend: ") + e.what();
    }
  }
  report(res.message, !res.success);
  return true;
}

bool RelocalizerNode::onRelocalize(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  std::string why;
  const auto future = relocalizeLatest(&why);
  res.success = false;
  if (!future) {
    res.message = "not localized: " + why;
    return true;
  }
  if (future->wait_for(std::chrono::duration<double>(params_.trigger_timeout_s)) != std::future_status::ready) {
    res.message = "not localized: no answer within trigger_timeout_s";
    return true;
  }
  const auto& reply = future->get();
  std::shared_ptr<MapState> state;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state = map_state_;
  }
  if (reply.dropped) res.message = "not localized: replaced by a newer request";
  else if (!reply.error.empty()) res.message = "not localized: " + reply.error;
  else if (!reply.ranking.localized || !state) res.message = "not localized: " + reply.ranking.reason;
  else {
    res.success = true;
    res.message = describe(reply.ranking.hypotheses.front(), *state->map);
    if (params_.mode == "track") reinitialize_tracker_ = true;
  }
  return true;
}

void RelocalizerNode::track(TrackJob& job) {
  auto& tracker = *job.state->tracker;
  if (reinitialize_tracker_.exchange(false)) tracker.reinitialize();
  std::optional<TrackerUpdate> u;
  try {
    u = tracker.update(job.scan, job.odom);
  } catch (const std::exception& e) {
    report(std::string("filter update failed: ") + e.what(), true);
    return;
  }
  if (!u) return;
  const double scan_interval_s = last_track_stamp_.isZero() ? 0.0 : (job.stamp - last_track_stamp_).toSec();
  last_track_stamp_ = job.stamp;
  const auto cost = guardCostNote(u->estimate.look_alike_search_cpu_s, u->estimate.look_alike_searches, scan_interval_s,
                                  params_.look_alike_recheck_every_updates);
  if (cost) {
    // Its numbers change every update, so report()'s repeat filter would let every one through.
    const ros::WallTime now = ros::WallTime::now();
    if (last_guard_note_time_.isZero() || (now - last_guard_note_time_).toSec() >= kProblemLogPeriodS) {
      last_guard_note_time_ = now;
      report(*cost, true);
    }
  }
  const OccupancyMap& map = *job.state->map;
  if (u->estimate.initialized && job.state->seeding->lastSeeding()) {
    const auto& seeding = *job.state->seeding->lastSeeding();
    publishHypotheses(seeding.ranking, map, job.stamp);
    std::ostringstream s;
    s << "filter seeded with " << seeding.particles << " particles"
      << (seeding.fell_back_to_uniform ? " (no hypothesis: uniform)" : "") << " from "
      << seeding.ranking.hypotheses.size() << " hypotheses";
    report(s.str(), seeding.fell_back_to_uniform);
  }
  std_msgs::Header header;
  header.stamp = job.stamp;
  header.frame_id = params_.global_frame;
  PoseHypothesis mean;
  mean.pose = u->estimate.mean;
  mean.cov = u->estimate.cov;
  amcl_pose_pub_.publish(initialPoseMsg(mean, map, header));
  if (u->estimate.ambiguous_with) {
    // A warning rather than silence: a consumer that ignores the covariance must still hear it.
    const auto other = map.toSourceFrame(*u->estimate.ambiguous_with);
    std::ostringstream s;
    s << std::fixed << std::setprecision(1) << "pose ambiguous: a look-alike place at (" << other.x << ", " << other.y
      << ") fits the scan nearly as well; the published covariance covers both";
    report(s.str(), true);
  }
  if (u->estimate.scan_unexplained) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(0) << "pose unsettled: only " << 100.0 * u->estimate.fit_fraction
      << " % of the scan's returns are explained by the map (clutter?); the published covariance is widened";
    report(s.str(), true);
  }
  if (u->estimate.look_alike_unverified && u->estimate.look_alike_search_pending)
    report(pendingSearchNote(params_.look_alike_max_nodes_per_update, params_.look_alike_unverified_is_unsettled), true);
  else if (u->estimate.look_alike_unverified)
    report(unverifiedPoseNote(params_.look_alike_max_search_nodes, params_.look_alike_unverified_is_unsettled), true);
  geometry_msgs::PoseArray cloud;
  cloud.header = header;
  const auto& pf = job.state->tracker->localizer().particles();
  for (size_t i = 0; i < pf.size(); ++i) cloud.poses.push_back(poseToRos(map.toSourceFrame(pf.getParticlePose(i))));
  cloud_pub_.publish(cloud);
  // Grid -> source frame as a pose composition, so map -> odom lands in the published map frame.
  const mrpt::poses::CPose2D grid_in_source(map.toSourceFrame(mrpt::math::TPose2D(0, 0, 0)));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    map_to_odom_ = (grid_in_source + mrpt::poses::CPose2D(u->map_to_odom)).asTPose();
  }
  broadcastMapToOdom(job.stamp);
}

void RelocalizerNode::broadcastMapToOdom(const ros::Time& scan_stamp) {
  std::optional<mrpt::math::TPose2D> t;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    t = map_to_odom_;
  }
  if (!t) return;
  // Future-dated like AMCL's, so that lookups at the latest scan time succeed until the next update.
  tf_broadcaster_.sendTransform(transformToRos(*t, params_.global_frame, params_.odom_frame,
                                               scan_stamp + ros::Duration(params_.transform_tolerance_s)));
}

void RelocalizerNode::publishHypotheses(const Ranking& ranking, const OccupancyMap& map, const ros::Time& stamp) {
  std_msgs::Header header;
  header.stamp = stamp;
  header.frame_id = params_.global_frame;
  hypotheses_pub_.publish(hypothesesPoseArray(ranking, map, header));
  markers_pub_.publish(hypothesesMarkers(ranking, map, header));
}

void RelocalizerNode::report(const std::string& text, bool problem) {
  if (problem) {
    // The same problem on every scan would flood the log and ~status: say it once, then at
    // most every few seconds.
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::WallTime now = ros::WallTime::now();
    if (text == last_problem_ && (now - last_problem_time_).toSec() < kProblemLogPeriodS) return;
    last_problem_ = text;
    last_problem_time_ = now;
  }
  std_msgs::String msg;
  msg.data = (problem ? "WARN " : "INFO ") + text;
  status_pub_.publish(msg);
  if (problem) ROS_WARN_STREAM("krp_relocalizer: " << text);
  else ROS_INFO_STREAM("krp_relocalizer: " << text);
}

}  // namespace krp::ros1
