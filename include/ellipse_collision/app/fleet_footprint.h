#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/app/transform_lookup.h"
#include "ellipse_collision/core/scene.h"

namespace ellipse_collision::app {

/// What a robot tells the fleet about itself (doc/fleet.md): its links, named
/// "<robot_name>/<link>", placed in a frame the fleet shares, each with its velocity there.
struct FleetSettings {
  bool enabled{true};
  std::string topic{"/fleet/footprints"};  ///< every robot on the master publishes here
  std::string frame{"map"};                ///< the frame the fleet shares
  std::string robot_name;                  ///< non-empty, no '/'; the node's namespace by default
  double rate{10.0};                       ///< [Hz] footprints a second, within (0, 100]
};

/// The first setting that cannot be used (keys as "fleet/frame"), or nothing.
std::optional<FieldError> findInvalidSetting(const FleetSettings& settings);

/// fleet/robot_name's default: the node's namespace without its slashes ("/r1" -> "r1",
/// "/site/r1" -> "site_r1"); in the root namespace, the node's own name (unique on a master, as
/// a namespace is), so that robots started without namespaces still tell each other apart.
std::string defaultFleetRobotName(const std::string& node_namespace, const std::string& node_name);

/// The robot's links placed in the fleet's frame, or why not.
struct PlacedLinks {
  std::vector<core::NamedEllipse> links;  ///< padded as every check pads them (placeInPlane())
  double stamp_s{0.0};  ///< the newest of their transforms' stamps [s]; 0 = all timeless
  std::string error;    ///< the first link that could not be placed, and why; "" = placed
};

/// Places `links` through `lookup` (into the fleet's frame) with `global_padding` [m]. A frame
/// that is stale under `freshness` (the node's max_transform_age) is an error like a missing one:
/// a robot whose localization stopped must fall silent, not repeat where it was.
PlacedLinks placeLinks(const std::vector<EllipseSpec>& links, double global_padding,
                       const TransformLookup& lookup, const Freshness& freshness);

/// The robot's own footprint, message after message. Each link's velocity is its motion since the
/// last footprint (the centre's displacement and the turn over the time between the two
/// placements, both from tf): what the robot did over the last interval, whatever commanded it.
/// A link seen for the first time, or after more than kMaxIntervalS, stands. A placement at the
/// same stamp as the last (tf had nothing newer: the footprint is sent faster than tf updates)
/// keeps the last velocity, so that a moving robot is not said to stand every other footprint.
class FleetFootprint {
 public:
  /// [s] an interval longer than this gives no velocity (a pause, a time jump).
  static constexpr double kMaxIntervalS = 1.0;

  /// `links` (placed in `frame` at `stamp_s` [s]) as the fleet gets them: named
  /// robot_name + "/" + link, frame_id `frame`, with velocities in its axes.
  std::vector<EllipseSpec> update(double stamp_s, const std::vector<core::NamedEllipse>& links,
                                  const std::string& robot_name, const std::string& frame);

 private:
  struct Seen {
    double stamp_s;
    core::Ellipse ellipse;
    double vx, vy, angular_velocity;  ///< what was said of it [m/s, rad/s]
  };
  std::unordered_map<std::string, Seen> last_;
};

}  // namespace ellipse_collision::app
