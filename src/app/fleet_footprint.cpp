#include "ellipse_collision/app/fleet_footprint.h"

#include <cmath>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

std::optional<FieldError> findInvalidSetting(const FleetSettings& s) {
  if (s.topic.empty()) return FieldError{"fleet/topic", "a non-empty topic name", "''"};
  if (s.frame.empty() || s.frame.front() == '/') {
    return FieldError{"fleet/frame", "a tf2 frame id, non-empty, without a leading '/'",
                      "'" + s.frame + "'"};
  }
  if (s.robot_name.empty() || s.robot_name.find('/') != std::string::npos) {
    return FieldError{"fleet/robot_name", "a non-empty name without '/'",
                      "'" + s.robot_name + "'"};
  }
  return findOutsideRange("fleet/rate", s.rate, 0.0, 100.0, true);
}

std::vector<EllipseSpec> FleetFootprint::update(double stamp_s,
                                                const std::vector<core::NamedEllipse>& links,
                                                const std::string& robot_name,
                                                const std::string& frame) {
  std::vector<EllipseSpec> footprint;
  footprint.reserve(links.size());
  std::unordered_map<std::string, Seen> now;
  for (const core::NamedEllipse& link : links) {
    const core::Ellipse& e = link.ellipse;
    EllipseSpec spec;
    spec.name = robot_name + "/" + link.name;
    spec.frame_id = frame;
    spec.x = e.center.x();
    spec.y = e.center.y();
    spec.angle = e.angle;
    spec.radius_x = e.radius_x;
    spec.radius_y = e.radius_y;
    const auto before = last_.find(link.name);
    if (before != last_.end()) {
      const double dt = stamp_s - before->second.stamp_s;
      if (dt > 0.0 && dt <= kMaxIntervalS) {
        spec.vx = (e.center.x() - before->second.ellipse.center.x()) / dt;
        spec.vy = (e.center.y() - before->second.ellipse.center.y()) / dt;
        // The turn, the shorter way round (an interval turns a link by less than pi).
        const double turn = e.angle - before->second.ellipse.angle;
        spec.angular_velocity = std::atan2(std::sin(turn), std::cos(turn)) / dt;
      }
    }
    now[link.name] = {stamp_s, e};
    footprint.push_back(spec);
  }
  last_ = std::move(now);
  return footprint;
}

}  // namespace ellipse_collision::app
