#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/field_error.h"

namespace ellipse_collision::app {

/// The other robots of the fleet, as this node keeps them: each robot's latest footprint (the
/// ellipses of a message grouped by the name before the first '/'), its own robot's ignored. A
/// robot silent for longer than the timeout is dropped (robots leave: that is no error). Their
/// links are obstacles with their velocities, named as published ("r2/base_link").
class FleetRoster {
 public:
  /// `own_name`: this robot's fleet/robot_name; `timeout_s` > 0.
  FleetRoster(std::string own_name, double timeout_s)
      : own_name_(std::move(own_name)), timeout_s_(timeout_s) {}

  /// A footprint message received at `now_s` [s], stamped `stamp_s` [s] (0 = unstamped: taken
  /// as seen at `now_s`): every ellipse must be named "<robot>/<link>", each name once, and pass
  /// findInvalidField(); otherwise the whole message is refused, naming the entry.
  /// Each robot in it replaces its previous links.
  std::optional<std::string> receive(double now_s, const std::vector<EllipseSpec>& ellipses,
                                     double stamp_s = 0.0);

  /// Drops the robots last heard from more than the timeout before `now_s`; their names. A robot
  /// last heard after `now_s` (the clock jumped back) counts as heard at `now_s`.
  std::vector<std::string> dropSilent(double now_s);

  /// Every other robot's links, robots in name order, each robot's advanced by its links'
  /// velocities from its own footprint's stamp to stamp(): the robots heard at different times
  /// as of one time, which the node then advances to the decision's time.
  std::vector<EllipseSpec> obstacles() const;
  /// The newest footprint's stamp [s] (0 = no robot kept): the time obstacles() holds.
  double stamp() const;

  struct Robot {
    std::string name;
    double age_s{0.0};  ///< since its last footprint [s]
    std::size_t links{0};
  };
  /// The robots kept, in name order, their ages at `now_s`.
  std::vector<Robot> robots(double now_s) const;

  /// What /diagnostics shows: "robots" (each kept robot with its age and link count) and
  /// "dropped" (robots dropped as silent and not heard from since).
  std::vector<std::pair<std::string, std::string>> healthValues(double now_s) const;

 private:
  struct Kept {
    double heard_s{0.0};
    double stamp_s{0.0};  ///< when its links were where they are
    std::vector<EllipseSpec> links;
  };
  std::string own_name_;
  double timeout_s_;
  std::map<std::string, Kept> robots_;
  std::set<std::string> dropped_;  ///< dropped as silent, not heard from since
};

}  // namespace ellipse_collision::app
