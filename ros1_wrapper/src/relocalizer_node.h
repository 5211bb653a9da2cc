// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "mrpt_krp_plugin/common/latest_only_worker.h"
#include "mrpt_krp_plugin/filter/kidnap_detector.h"
#include "mrpt_krp_plugin/filter/odometry_tracker.h"
#include "mrpt_krp_plugin/map/occupancy_map.h"
#include "mrpt_krp_plugin/relocalize/async_relocalizer.h"
#include "mrpt_krp_plugin/relocalize/scan_fit.h"
#include "node_params.h"

namespace krp::ros1 {

/// krp_relocalizer_node: converts messages and calls the library. Inference runs on the
/// library's worker threads; callbacks only convert, look up transforms and hand over.
///
/// Topics in: `map` (unless ~map_file), `scan`, tf, `amcl_pose` (relocalize mode, for kidnap
/// detection). Out: `initialpose`, `~hypotheses`, `~hypothesis_markers`, `~status`; in track
/// mode also `amcl_pose`, `particlecloud` and the map -> odom transform, and it takes a pose
/// given on `initialpose` (RViz's "2D Pose Estimate") as AMCL does.
/// Services: `global_localization` (std_srvs/Empty, AMCL's name and type), `~relocalize`
/// (std_srvs/Trigger: answers with the pose and confidence, or why not localized).
class RelocalizerNode {
 public:
  /// InputError for bad parameters or an unreadable ~map_file.
  RelocalizerNode(ros::NodeHandle nh, ros::NodeHandle private_nh);
  ~RelocalizerNode();

 private:
  /// Everything that depends on the map, rebuilt when a new map arrives.
  struct MapState {
    std::shared_ptr<const OccupancyMap> map;
    std::unique_ptr<AsyncRelocalizer> relocalizer;
    std::unique_ptr<ScanFitScorer> fit;  ///< relocalize mode: kidnap detection at AMCL's pose
    std::shared_ptr<SeededInitializer> seeding;  ///< track mode
    std::shared_ptr<OdometryTracker> tracker;    ///< track mode: used by the track worker only
    /// Track mode: a pose a user gave on `initialpose`; the next seeding uses it instead of the relocalizer.
    std::shared_ptr<std::optional<Ranking>> user_pose;
    std::shared_ptr<std::mutex> user_pose_mutex;
  };
  struct TrackJob {
    mrpt::obs::CObservation2DRangeScan::Ptr scan;
    mrpt::math::TPose2D odom;
    ros::Time stamp;
    std::shared_ptr<MapState> state;
  };

  void useMap(OccupancyMap map);
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg);
  void onAmclPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg);
  void onInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg);
  bool onGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool onRelocalize(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res);
  /// Re-reads the models (a file replaced on disk is not used until then) on the map in use; if
  /// they do not load, keeps the loaded ones and says why.
  bool onReload(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res);

  /// Relocalizes from the newest scan; empty if there is no map or no recent scan (reason given).
  std::optional<std::shared_future<RelocalizationReply>> relocalizeLatest(std::string* why_not);
  void onReply(const RelocalizationReply& reply, const std::shared_ptr<const OccupancyMap>& map);
  void track(TrackJob& job);
  std::shared_ptr<MapState> mapState();  ///< the map in use, or null before the first
  void checkKidnap(const mrpt::obs::CObservation2DRangeScan& scan, const ros::Time& stamp);
  void publishHypotheses(const Ranking& ranking, const OccupancyMap& map, const ros::Time& stamp);
  void broadcastMapToOdom(const ros::Time& scan_stamp);
  /// Logs and publishes on ~status; `problem` also logs as a warning (throttled per text).
  void report(const std::string& text, bool problem);

  NodeParams params_;
  ros::NodeHandle nh_, pnh_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  ros::Publisher initialpose_pub_, hypotheses_pub_, markers_pub_, status_pub_, amcl_pose_pub_, cloud_pub_;
  ros::Subscriber map_sub_, scan_sub_, amcl_pose_sub_, initialpose_sub_;
  ros::ServiceServer global_localization_srv_, relocalize_srv_, reload_srv_;

  std::mutex mutex_;  ///< guards everything below
  std::shared_ptr<MapState> map_state_;
  std::optional<RelocalizationRequest> latest_;
  bool relocalization_pending_ = false;  ///< startup, service or kidnap: relocalize at the next scan
  std::optional<mrpt::math::TPose2D> amcl_pose_;  ///< grid frame
  ros::Time amcl_pose_stamp_;
  KidnapDetector kidnap_;
  std::optional<mrpt::math::TPose2D> map_to_odom_;  ///< track mode, source map frame
  std::string last_problem_;
  ros::WallTime last_problem_time_;

  // Track mode: the filter runs on its own thread.
  std::atomic<bool> reinitialize_tracker_{false};
  ros::Time last_track_stamp_;          ///< the track worker's previous scan (its thread only)
  ros::WallTime last_guard_note_time_;  ///< when the guard's cost was last reported (its thread only)
  std::unique_ptr<LatestOnlyWorker<TrackJob>> track_worker_;
};

}  // namespace krp::ros1
