#pragma once

#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ellipse_collision/ros/collision_markers.h"
#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/obstacle_persistence.h"
#include "ellipse_collision/ros/messages.h"
#include "ellipse_collision/ros/node_config.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision {

/// ellipse_collision_node: keeps links and obstacles attached to tf frames, checks them in the
/// plane of `fixed_frame` and serves the results (README: parameters, topics, services).
/// Single-threaded: every callback runs from ros::spin(), tf arrives on the listener's own thread.
class CollisionNode {
 public:
  /// Reads and validates the private parameters first; throws ConfigError on a bad configuration
  /// before it advertises anything.
  CollisionNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh);
  /// Writes runtime obstacles not yet in ~obstacle_store before the node goes.
  ~CollisionNode();

 private:
  /// The last full check (all stored ellipses, latest transforms), which the topics show.
  struct PublishedState {
    bool valid{false};
    ros::Time stamp;
    app::CheckOutcome outcome;
    double duration_s{0.0};
    std::string failure;  ///< why the latest full check failed (the state above is older)
  };

  /// Checks every stored ellipse at the latest transforms, records the result as the published
  /// state and publishes it (a failed check is only logged and reported in diagnostics).
  /// Clears the tf buffer when ros::Time went backwards (a looping bag) and drops topic
  /// obstacles older than ~obstacle_timeout; every check starts here.
  void handleTimeJumpAndExpiry();
  /// When a full check publishes ~collisions: the periodic check every time (the topic's rhythm
  /// is `rate`); a service call only when the state differs from the one last published, or
  /// always when there is no periodic check (rate 0). A client calling at 1 kHz then neither
  /// floods the topic nor pays a serialisation and a wake-up of the publishing thread per call.
  enum class StatePublishing { Always, OnChange };
  /// The outcome is state_.outcome on success, failed_check_ otherwise (no copy per cycle).
  const app::CheckOutcome& runFullCheck(const ros::Duration& timeout,
                                 StatePublishing publishing,
                                 const std::string& min_distance_of = "");
  /// Restores the runtime obstacles of an earlier run of this node in the same launch session
  /// (roslaunch's /run_id) from ~obstacle_store; a missing, corrupt or foreign store is logged and
  /// the node starts without it. Returns the service_revision this launch's files counted.
  std::uint64_t restoreObstacles();
  /// After an accepted service call: persistence_'s rule, the error logged. "" or why the change
  /// is not durable (the services answer success only once it is).
  std::string persistServiceCall(bool removed_topic_obstacle);
  /// For ~obstacles messages and expiry: the store is written in the background, at most once
  /// per ~obstacle_store_period (0: after every message), so a perception stream never waits
  /// for the disk.
  void persistObstaclesLater();
  void onStoreTimer(const ros::WallTimerEvent& event);
  void logStoreError(const std::string& error) const;
  void publishState(StatePublishing publishing);
  void publishMarkers();

  void onTimer(const ros::TimerEvent& event);
  void onDiagnosticsTimer(const ros::TimerEvent& event);
  void onMarkerSubscriber(const ros::SingleSubscriberPublisher& subscriber);
  void onObstacles(const EllipseArray::ConstPtr& msg);
  bool onCheckCollisions(CheckCollisions::Request& request, CheckCollisions::Response& response);
  bool onAddObstacles(AddObstacles::Request& request, AddObstacles::Response& response);
  bool onRemoveObstacles(RemoveObstacles::Request& request, RemoveObstacles::Response& response);
  bool onCheckPath(CheckPath::Request& request, CheckPath::Response& response);
  /// The time-to-contact step (app::predictContacts()) of a successful check; nothing when
  /// ~prediction_horizon is 0.
  /// `stamp`: the check's transform time (zero = latest); predicted times count from `reference`
  /// (the check's stamp; zero = `stamp`, or now for latest transforms).
  void predict(app::CheckOutcome& outcome, const app::CheckRequest& request, const ros::Time& stamp,
               const ros::Time& reference = ros::Time(0));

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_;
  NodeConfig config_;
  app::CheckSettings settings_;
  app::EllipseRegistry registry_;
  /// Projections reused from one full check to the next while frames do not move.
  app::PlacementCache placement_cache_;
  app::CheckOutcome failed_check_;

  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;

  ros::Publisher collisions_pub_;
  ros::Publisher markers_pub_;
  ros::Publisher diagnostics_pub_;
  ros::Subscriber obstacles_sub_;
  ros::ServiceServer check_service_;
  ros::ServiceServer add_service_;
  ros::ServiceServer remove_service_;
  ros::ServiceServer path_service_;
  ros::Timer check_timer_;
  ros::Timer diagnostics_timer_;
  ros::WallTimer store_timer_;  ///< writes the store when ~obstacles changed it (wall time: a
                                ///< paused simulation clock does not hold back durability)

  CollisionMarkers markers_;
  /// When ~markers last went out to a subscriber (zero while there was none): the refresh
  /// sweep's share of the period since then.
  ros::WallTime last_markers_time_;
  PublishedState state_;
  CollisionState last_state_msg_;  ///< the ~collisions message last published
  bool state_published_{false};
  std::string last_obstacles_error_;  ///< why the last ~obstacles message was refused, if it was
  std::uint64_t full_checks_{0};
  std::map<std::string, ros::Time> missing_since_;  ///< frame -> first full check it was missing
  ros::Time last_now_;                              ///< time of the last check, to see jumps back
  std::uint64_t dropped_obstacles_{0};              ///< dropped by ~obstacle_timeout
  std::uint64_t time_jumps_{0};
  std::string obstacle_store_;  ///< path of the store; "" = off
  std::string session_;         ///< /run_id of this launch
  std::unique_ptr<app::ObstaclePersistence> persistence_;  ///< the store's rule and its writer
};

}  // namespace ellipse_collision
