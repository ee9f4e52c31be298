#pragma once

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_monitor.h"
#include "ellipse_collision/core/scene_check.h"
#include "ellipse_collision/ros/collision_markers.h"
#include "ellipse_collision/ros/fleet_publisher.h"
#include "ellipse_collision/ros/gate_markers.h"
#include "ellipse_collision/ros/incident_writer.h"
#include "ellipse_collision/ros/messages.h"
#include "ellipse_collision/ros/node_config.h"
#include "ellipse_collision/ros/reconfigure.h"
#include "ellipse_collision/ros/source_subscribers.h"
#include "ellipse_collision/ros/tf_listener.h"

namespace ellipse_collision {

/// The node's configuration from its private namespace: loadNodeConfig() with `links_from_urdf`
/// fitted by fitUrdfLinksFromParam() (URDF and meshes). The node and its --check-config guard
/// both validate through this one call, so the guard refuses exactly what the node refuses.
/// Throws ConfigError.
NodeConfig loadCollisionNodeConfig(const ros::NodeHandle& private_nh);

/// ellipse_collision_node: the ROS edge of app::CollisionMonitor. It reads the parameters, binds
/// tf, converts messages, advertises and publishes; every rule is the monitor's.
/// Single-threaded: every callback runs from ros::spin(), tf arrives on the listener's own thread.
class CollisionNode {
 public:
  /// Reads and validates the private parameters first; throws ConfigError on a bad configuration
  /// before it advertises anything.
  CollisionNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh);
  /// The monitor writes runtime obstacles not yet in ~obstacle_store before the node goes.
  ~CollisionNode() = default;

 private:
  /// After a check: a new state goes out on ~collisions (as the monitor says) and ~markers.
  void publishIfUpdated();
  void logPredictionNotes(const app::CheckOutcome& outcome) const;
  void publishState(app::StatePublishing publishing);
  void publishMarkers();
  /// tf answering for the fixed frame at `stamp` (zero = latest), waiting up to `timeout`.
  app::TransformLookup lookup(const ros::Time& stamp, const ros::Duration& timeout) const;
  /// tf answering for a frame's pose in the fixed frame at a given time, without waiting.
  app::TransformAtLookup lookupAt() const;

  void onTimer(const ros::TimerEvent& event);
  void onStoreTimer(const ros::WallTimerEvent& event);
  void onDiagnosticsTimer(const ros::TimerEvent& event);
  void onMarkerSubscriber(const ros::SingleSubscriberPublisher& subscriber);
  /// /diagnostics' "fleet" status: what is published (or why not) and each robots source's
  /// robots; none when the fleet is off and no robots source is listed.
  std::optional<diagnostic_msgs::DiagnosticStatus> fleetStatus(double now_s) const;
  bool onCheckCollisions(CheckCollisions::Request& request, CheckCollisions::Response& response);
  bool onAddObstacles(AddObstacles::Request& request, AddObstacles::Response& response);
  bool onRemoveObstacles(RemoveObstacles::Request& request, RemoveObstacles::Response& response);
  bool onCheckPath(CheckPath::Request& request, CheckPath::Response& response);
  /// ~cmd_vel_in: gated in this callback, one ~cmd_vel_out per command.
  void onCommand(const geometry_msgs::Twist::ConstPtr& msg);
  void onGateWatchdog(const ros::TimerEvent& event);
  bool onSetGateEnabled(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  /// ~cmd_vel_out, ~gate_state and ~gate_markers for one decision.
  void publishGate(const app::GateDecision& decision, const ros::Time& stamp);
  /// The recorder's finished incidents to the writer's thread; returns the last one's path.
  std::string writeIncidents(const ros::Time& now);
  void onIncidentTimer(const ros::TimerEvent& event);
  /// ~save_incident: the recorder's buffer as it is now, written at once.
  bool onSaveIncident(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  /// The incident recorder's /diagnostics status: OK, or WARN while its last write failed.
  diagnostic_msgs::DiagnosticStatus incidentStatus() const;
  /// dynamic_reconfigure (~ and ~gate): the request passes the monitor's rules (retune()) or is
  /// refused whole and logged; either way `config` is set to the values in force, which the
  /// server then reports.
  void onCheckReconfigure(CheckParametersConfig& config, std::uint32_t level);
  void onGateReconfigure(GateParametersConfig& config, std::uint32_t level);
  /// gate/odom_topic: the base's measured twist, for the braking rule.
  void onOdometry(const nav_msgs::Odometry::ConstPtr& msg);
  /// The log line while the gate assumes a base that stops at once (app::idealBaseWarning()).
  void warnIfIdealBase() const;
  /// Takes `tunable` (unless a value was at a slider's bound: `at_bound`), or logs why not; the
  /// timers follow the rate and cmd_vel_timeout in force.
  void retune(const std::optional<app::FieldError>& at_bound, const app::TunableSettings& tunable);
  /// The periodic check at the monitor's rate (none at 0), the gate's watchdog at a quarter of its
  /// cmd_vel_timeout (none at 0).
  void scheduleTimers();

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_;
  NodeConfig config_;
  tf2_ros::Buffer tf_buffer_;
  TfListener tf_listener_;
  /// The algorithm: stored ellipses, checks, state, health, persistence.
  std::unique_ptr<app::CollisionMonitor> monitor_;

  ros::Publisher collisions_pub_;
  ros::Publisher markers_pub_;
  ros::Publisher diagnostics_pub_;
  /// ~obstacles and the listed sources, each message's obstacles to the monitor.
  std::unique_ptr<SourceSubscribers> sources_;
  /// fleet/: this robot's links for the others; null while fleet/enabled is false.
  std::unique_ptr<FleetPublisher> fleet_;
  ros::ServiceServer check_service_;
  ros::ServiceServer add_service_;
  ros::ServiceServer remove_service_;
  ros::ServiceServer path_service_;
  ros::Timer check_timer_;
  ros::Timer diagnostics_timer_;
  ros::Subscriber cmd_vel_sub_;
  ros::Publisher cmd_vel_pub_;
  ros::Publisher gate_state_pub_;
  ros::Publisher gate_markers_pub_;
  ros::ServiceServer gate_enable_service_;
  ros::Timer gate_watchdog_timer_;
  ros::Subscriber odom_sub_;
  GateMarkers gate_markers_;
  /// Incident bags off the command's path; null while incident/enabled is false.
  std::unique_ptr<IncidentWriter> incident_writer_;
  ros::ServiceServer save_incident_service_;
  ros::Timer incident_timer_;
  std::unique_ptr<dynamic_reconfigure::Server<CheckParametersConfig>> check_reconfigure_;
  std::unique_ptr<dynamic_reconfigure::Server<GateParametersConfig>> gate_reconfigure_;
  ros::WallTimer store_timer_;  ///< writes the store when ~obstacles changed it (wall time: a
                                ///< paused simulation clock does not hold back durability)

  CollisionMarkers markers_;
  /// When ~markers last went out to a subscriber (zero while there was none): the refresh
  /// sweep's share of the period since then.
  ros::WallTime last_markers_time_;
  CollisionState last_state_msg_;  ///< the ~collisions message last published
  bool state_published_{false};
};

}  // namespace ellipse_collision
