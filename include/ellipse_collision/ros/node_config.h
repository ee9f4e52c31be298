#pragma once

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/command_gate.h"
#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/link_fitting.h"
#include "ellipse_collision/app/scan_obstacles.h"
#include "ellipse_collision/app/tunable_settings.h"

namespace ellipse_collision {

/// A configuration the node cannot run with; what() names the entry, the key, expected and actual.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The scalar parameters' ranges live with their rule in the application layer (the same at
// start-up and when reconfigured).
using app::kMaxDurationS;
using app::kMaxPredictionHorizonS;
using app::kMaxRateHz;
using app::kMinRateHz;

constexpr double kMaxObstaclesLimit = 1e7;   ///< max_obstacles within [1, kMaxObstaclesLimit]
constexpr double kMaxNameLengthLimit = 1e6;  ///< max_name_length within [1, kMaxNameLengthLimit]

/// The node's private parameters (see config/ellipse_collision.yaml for the documentation).
struct NodeConfig {
  std::string fixed_frame{"base_link"};
  std::string robot_frame{"base_link"};  ///< ~check_path's moving frame when the request has none
  double prediction_horizon_s{0.0};      ///< time-to-contact prediction [s]; 0 = off
  double rate_hz{10.0};       ///< periodic checks [Hz]; 0 = only on service calls, else [1e-3, 1e3]
  double tf_timeout_s{0.1};   ///< how long a service call waits for a transform [s], [0, 3600]
  double padding_m{0.0};      ///< added to both radii of every ellipse [m], [0, kMaxRadius]
  bool self_collision{true};  ///< also check link against link
  double warning_distance_m{0.0};  ///< separated pairs closer than this are warnings [m]; 0 = off
  double max_transform_age_s{0.5};  ///< older non-static transforms are stale [s]; 0 = off
  double obstacle_timeout_s{0.0};   ///< ~obstacles older than this are dropped [s]; 0 = never
  app::RegistryLimits limits;       ///< max_obstacles, max_name_length
  /// File that keeps the runtime obstacles across a crash; unset = defaultObstacleStore(),
  /// "" = off.
  std::optional<std::string> obstacle_store;
  /// Longest wait before a change from ~obstacles (or its expiry) is written to the store [s];
  /// 0 = after every message. The services' changes are written before they answer.
  double obstacle_store_period_s{1.0};
  /// Every ~markers marker is sent again within this period, a slice per published array, so a
  /// subscriber that lost arrays heals [s]; 0 = off.
  double marker_refresh_period_s{10.0};
  std::vector<app::EllipseSpec> links;  ///< `links` entries, then those of `links_from_urdf`
  /// Links of `links_from_urdf` that were skipped, and why ("base_footprint: no collision
  /// geometry"); the node logs them at start-up.
  std::vector<std::string> urdf_links_skipped;
  std::vector<app::EllipseSpec> obstacles;
  std::vector<std::pair<std::string, std::string>> allowed_pairs;
  app::GateConfig gate;  ///< `gate/`: the velocity gate on ~cmd_vel_in (off by default)
};

/// How a configuration error reads, at start-up and when reconfigured: "<where>, key '<key>':
/// expected <expected>, got <actual>" (where: "parameter ~rate", "links[2]").
std::string describeConfigError(const std::string& where, const app::FieldError& error);

/// Fits the link ellipses of `links_from_urdf`: the URDF in parameter `param`, the links and
/// padding of `options`. Throws a std::runtime_error naming the parameter (or link, mesh URI) on
/// failure. The node passes ros/urdf_links.h's reader (urdfLinkFitter()); tests pass their own.
using UrdfLinkFitter =
    std::function<app::LinkFitResult(const std::string& param, const app::LinkFitOptions& options)>;

/// Parses and validates the node's private namespace given as one XmlRpc struct. `links` is
/// required (an empty list is fine) unless `links_from_urdf` is given, every other key optional;
/// unknown keys are errors, so that a typo cannot silently fall back to a default. Integers are
/// accepted where a double is expected. Values out of their documented range are refused, never
/// clamped; every ellipse must pass findInvalidPaddedField() with the global padding.
/// `links_from_urdf: {param, links, padding}` appends the ellipses `fit_urdf_links` fits to
/// `links` (an empty `fit_urdf_links` makes it an error). Throws ConfigError.
NodeConfig parseNodeConfig(const XmlRpc::XmlRpcValue& params,
                           const UrdfLinkFitter& fit_urdf_links = {});

/// Parses a list of ellipses as the node's `links` and `obstacles` are given: each entry a dict
/// {name, frame, x, y, angle, radius_x, radius_y, padding (optional)} [m, rad], its fields checked
/// with app::findInvalidPaddedField() and `global_padding` [m]. `key` names the list in messages
/// (`key[i]`). Names are not checked against each other. Throws ConfigError naming the entry, the
/// key, expected and actual value.
std::vector<app::EllipseSpec> parseEllipseList(const XmlRpc::XmlRpcValue& list,
                                               const std::string& key, double global_padding);

/// $ROS_HOME (else ~/.ros)/ellipse_collision/<node name, '/' -> '_'>.obstacles.
std::string defaultObstacleStore(const std::string& node_name);

/// Reads the whole private namespace of `private_nh` from the parameter server and parses it.
/// Throws ConfigError.
NodeConfig loadNodeConfig(const ros::NodeHandle& private_nh,
                          const UrdfLinkFitter& fit_urdf_links = {});

/// Parses scan_obstacles' private namespace (every key optional, documented defaults in
/// app::ScanObstacleSettings; unknown keys and wrong types are errors; ranges from
/// app::findInvalidSetting()). Throws ConfigError naming the key.
app::ScanObstacleSettings parseScanObstacleSettings(const XmlRpc::XmlRpcValue& params);

/// Reads scan_obstacles' private namespace from the parameter server and parses it.
app::ScanObstacleSettings loadScanObstacleSettings(const ros::NodeHandle& private_nh);

}  // namespace ellipse_collision
