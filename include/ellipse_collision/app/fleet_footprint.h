#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/field_error.h"
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

/// The robot's own footprint, message after message. Each link's velocity is its motion since the
/// last footprint (the centre's displacement and the turn over the time between the two
/// placements, both from tf): what the robot did over the last interval, whatever commanded it.
/// A link seen for the first time, or after more than kMaxIntervalS, stands.
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
  };
  std::unordered_map<std::string, Seen> last_;
};

}  // namespace ellipse_collision::app
