#pragma once

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/collision_monitor.h"
#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/fleet_footprint.h"
#include "ellipse_collision/app/gate_config.h"
#include "ellipse_collision/app/tunable_settings.h"
#include "ellipse_collision/ros/ellipse_params.h"
#include "ellipse_collision/ros/param_reading.h"

namespace ellipse_collision {

// The scalar parameters' ranges live with their rule in the application layer (the same at
// start-up and when reconfigured).
using app::kMaxDurationS;
using app::kMaxPredictionHorizonS;
using app::kMaxRateHz;
using app::kMinRateHz;

constexpr double kMaxObstaclesLimit = 1e7;   ///< max_obstacles within [1, kMaxObstaclesLimit]
constexpr double kMaxNameLengthLimit = 1e6;  ///< max_name_length within [1, kMaxNameLengthLimit]

/// The node's defaults where they differ from the application layer's own: max_transform_age
/// 0.5 s (config/ellipse_collision.yaml).
app::MonitorSettings nodeMonitorDefaults();

/// The node's private parameters (see config/ellipse_collision.yaml for the documentation).
struct NodeConfig {
  /// What the application layer runs with, parsed straight into its settings: fixed_frame,
  /// robot_frame, rate, padding, self_collision, warning_distance, max_transform_age,
  /// obstacle_timeout, prediction_horizon, obstacle_store_period, allowed_pairs, gate/ and
  /// incident/.
  app::MonitorSettings monitor{nodeMonitorDefaults()};
  double tf_timeout_s{0.1};  ///< how long a service call waits for a transform [s], [0, 3600]
  app::RegistryLimits limits;       ///< max_obstacles, max_name_length
  /// File that keeps the runtime obstacles across a crash; unset = defaultObstacleStore(),
  /// "" = off.
  std::optional<std::string> obstacle_store;
  /// Every ~markers marker is sent again within this period, a slice per published array, so a
  /// subscriber that lost arrays heals [s]; 0 = off.
  double marker_refresh_period_s{10.0};
  std::vector<app::EllipseSpec> links;  ///< `links` entries, then those of `links_from_urdf`
  /// Links of `links_from_urdf` that were skipped, and why ("base_footprint: no collision
  /// geometry"); the node logs them at start-up.
  std::vector<std::string> urdf_links_skipped;
  std::vector<app::EllipseSpec> obstacles;
  /// `fleet/`: what the node tells the other robots about its own (FleetFootprint); its
  /// robot_name is also the one a robots source ignores.
  app::FleetSettings fleet;
};

/// Parses and validates the node's private namespace given as one XmlRpc struct. `links` is
/// required (an empty list is fine) unless `links_from_urdf` is given, every other key optional;
/// unknown keys are errors, so that a typo cannot silently fall back to a default. Integers are
/// accepted where a double is expected. Values out of their documented range are refused, never
/// clamped; every ellipse must pass findInvalidPaddedField() with the global padding.
/// `links_from_urdf: {param, links, padding}` appends the ellipses `fit_urdf_links` fits to
/// `links` (an empty `fit_urdf_links` makes it an error). `default_robot_name` is
/// fleet/robot_name's default (app::defaultFleetRobotName() of the node). Throws ConfigError.
NodeConfig parseNodeConfig(const XmlRpc::XmlRpcValue& private_namespace,
                           const UrdfLinkFitter& fit_urdf_links = {},
                           const std::string& default_robot_name = "robot");

/// $ROS_HOME, else ~/.ros (else /tmp without a home).
std::string rosHome();
/// $ROS_HOME (else ~/.ros)/ellipse_collision/<node name, '/' -> '_'>.obstacles.
std::string defaultObstacleStore(const std::string& node_name);
/// Where incident bags go unless incident/directory says: rosHome()/ellipse_collision/incidents.
std::string defaultIncidentDirectory();

/// Reads the whole private namespace of `private_nh` from the parameter server and parses it.
/// Throws ConfigError.
NodeConfig loadNodeConfig(const ros::NodeHandle& private_nh,
                          const UrdfLinkFitter& fit_urdf_links = {});

}  // namespace ellipse_collision
