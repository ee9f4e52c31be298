#pragma once

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "demo_arm_guard.h"
#include "demo_base_control.h"
#include "demo_log_on_change.h"
#include "demo_scanner.h"
#include "demo_trajectory.h"
#include "demo_world.h"
#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/core/simulated_base.h"

namespace ellipse_collision {

/// A demo parameter the driver cannot run with; what() names the parameter.
class DemoConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// demo_driver: drives the demo robot through the collision node's velocity gate, moves the
/// joints along DemoTrajectory and one obstacle of its DemoWorld along its shuttle. The base: every
/// cycle BaseScript's command goes out on `cmd_vel` (the launch remaps it to the node's
/// ~cmd_vel_in), and the base moves only by the gated command on `cmd_vel_gated` (the node's
/// ~cmd_vel_out), integrated exactly as an arc from one cycle to the next; the odom -> base
/// transform is that pose. Publishes joint_states (for robot_state_publisher), the odom -> base
/// transform, and what a planar laser scanner at the scanner frame sees of the whole world (the
/// static obstacles and the moving one), as a sensor_msgs/LaserScan on `scan` (which scan_obstacles
/// turns into the collision node's ~obstacles: the only way the node learns of them). The service
/// ~pause (std_srvs/SetBool) stops and restarts the demo clock; while paused everything is still
/// published, with fresh stamps, at the same pose, so tf stays current and the scene stays still;
/// no command goes out (the gate's cmd_vel_timeout zeroes it) and the base stands.
/// The base's plan: every cycle the next `planned_path/horizon` seconds of its command held (the
/// arc the gate judges, before the gate), as a timed
/// nav_msgs/Path on `planned_path` (in the odom frame, one pose per `planned_path/step`); at
/// `planned_path/check_rate` the driver checks it with the collision node's ~check_path and shows
/// the answer on ~path_check_markers: the first contact as a magenta ring at the base's pose then
/// (DELETE while the plan is clear).
/// The arm (`arm_guard`): every cycle, before the joints move on along their sweep, the links'
/// motion over the next `arm_guard/horizon` seconds goes to the collision node's
/// ~check_collisions as query ellipses; while a link would come within `arm_guard/clearance` of
/// an obstacle the joints hold (demo_arm_guard.h), drawn on ~path_check_markers as the link's
/// outline where it would touch and a text "arm held: ...".
class DemoDriver {
 public:
  /// Reads the private parameters (demo/config/demo_driver.yaml); throws DemoConfigError.
  DemoDriver(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh);

 private:
  void onTimer(const ros::TimerEvent& event);
  /// Publishes the scan of the `world` ellipses seen from the base at `base` (both in the odom
  /// frame), once tf knows where the scanner sits on the base.
  void publishScan(const ros::Time& now, const Pose2D& base,
                   const std::vector<core::Ellipse>& world);
  bool onPause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  /// The next planned_horizon_s of `command` held from the base's pose, stamped from `now`.
  nav_msgs::Path plannedPath(const ros::Time& now, const core::Twist& command) const;
  void onGatedCommand(const geometry_msgs::Twist& gated);
  void onPathCheckTimer(const ros::TimerEvent& event);
  /// Reads `base` (the simulated base's reaction time and deceleration limits).
  void readBaseDynamics();
  /// The base's pose and measured twist on `odom` (nav_msgs/Odometry), as a base driver does.
  void publishOdometry(const ros::Time& now);
  /// Reads `arm_guard` and, when enabled, the collision node's configuration (its links and
  /// warning distance) and the arm's chains from the URDF in robot_description.
  void setUpArmGuard();
  /// Checks the arm's next motion from arm_clock_s_ and moves the arm clock on by `dt_s` unless
  /// the joints must hold; draws and logs the hold.
  void guardArm(const ros::Time& now, double dt_s);
  /// Why the arm must hold now ("" = it may move): the hold rule on the node's answer, or a
  /// check that failed or could not decide.
  /// `direction` +1: the arm's next motion along its sweep; -1: back along it.
  std::string armHoldReason(double direction, std::optional<ArmHold>* hold);
  void publishArmHold(const ros::Time& now, const std::string& text,
                      const std::optional<ArmHold>& hold);
  /// The demo clock [s]: ROS time since start, minus the time spent paused.
  double demoTime(const ros::Time& now) const;

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_;
  std::string odom_frame_;
  std::string base_frame_;
  DemoTrajectory trajectory_;
  std::unique_ptr<BaseScript> base_script_;
  Pose2D base_;  ///< the base's pose in the odom frame, as base_sim_ moved it
  core::BaseDynamics base_dynamics_{0.1, 1.0, 2.0};  ///< `base`: how the simulated base follows
  /// The base, following the gated commands late and braking at bounded rates (demo clock).
  std::optional<core::SimulatedBase> base_sim_;
  core::Twist command_;         ///< the last command sent on cmd_vel
  core::Twist gated_;           ///< the last gated command received; the base moves by it
  bool gated_since_command_{false};  ///< a gated command arrived since the last command
  DemoWorld world_;             ///< what the scanner sees, in the odom frame
  std::string moving_name_;     ///< the moving obstacle's name (for the log)
  std::string scanner_frame_;
  ScannerModel scanner_;

  tf2_ros::TransformBroadcaster tf_broadcaster_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_{tf_buffer_};
  ros::Publisher joint_states_pub_;
  ros::Publisher cmd_vel_pub_;
  ros::Subscriber gated_sub_;
  ros::Publisher scan_pub_;
  ros::Publisher odom_pub_;
  ros::ServiceServer pause_service_;
  ros::Timer timer_;
  ros::Publisher planned_path_pub_;
  ros::Publisher path_check_markers_pub_;
  ros::ServiceClient check_path_;
  ros::Timer path_check_timer_;
  nav_msgs::Path last_plan_;
  /// The first seconds after launch, while the other nodes connect and the first transforms
  /// arrive: a missing transform is logged at DEBUG, not WARN.
  static constexpr double kStartUpS = 5.0;
  ros::Time launched_;                ///< ROS time at which the driver started
  bool path_check_succeeded_{false};  ///< ~check_path has answered successfully at least once
  double planned_horizon_s_{3.0};  ///< [s] of the loop ahead in each plan
  double planned_step_s_{0.1};     ///< [s] between its poses

  // The arm guard (arm_guard): the arm's own clock runs with the demo clock while the next
  // motion is clear and stands while the joints hold.
  bool arm_guard_enabled_{true};
  ArmGuardSettings arm_guard_;
  std::vector<ArmLink> arm_links_;
  std::vector<SineMotion> joint_motions_;  ///< trajectory_'s motions, in its order
  std::set<std::string> node_links_;       ///< the collision node's links: never obstacles
  double warning_distance_m_{0.0};         ///< the node's ~warning_distance
  ros::ServiceClient check_collisions_;
  double arm_clock_s_{0.0};    ///< [s] the time along the joints' sweep
  double last_demo_t_s_{0.0};  ///< the demo clock at the last cycle [s]
  std::string arm_hold_text_;  ///< what the hold marker shows; "" = not held
  double arm_held_s_{0.0};     ///< [s] how long the arm has held for an obstacle without a break
  double arm_retreat_left_s_{0.0};  ///< [s] of the sweep still to back off along; 0 = forward
  std::string arm_retreat_text_;    ///< what the marker shows while the arm backs off
  ros::Time arm_marker_sent_;
  LogOnChange arm_log_{5.0};
  LogOnChange plan_log_{5.0};

  bool paused_{false};
  double clock_at_start_s_{0.0};  ///< demo clock when it last (re)started or paused [s]
  ros::Time started_;             ///< ROS time at which it last (re)started
};

}  // namespace ellipse_collision
