#include "ellipse_collision/app/fleet_footprint.h"

#include <algorithm>
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
    return FieldError{"fleet/robot_name", "a non-empty name without '/'", "'" + s.robot_name + "'"};
  }
  return findOutsideRange("fleet/rate", s.rate, 0.0, 100.0, true);
}

std::string defaultFleetRobotName(const std::string& node_namespace, const std::string& node_name) {
  std::string name;
  for (const char c : node_namespace) {
    if (c != '/') {
      name += c;
    } else if (!name.empty()) {
      name += '_';
    }
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  if (!name.empty()) return name;
  const std::size_t slash = node_name.rfind('/');
  return slash == std::string::npos ? node_name : node_name.substr(slash + 1);
}

PlacedLinks placeLinks(const std::vector<EllipseSpec>& links, double global_padding,
                       const TransformLookup& lookup, const Freshness& freshness) {
  PlacedLinks placed;
  std::unordered_map<std::string, FrameTransform> frames;  // one lookup per frame
  for (const EllipseSpec& link : links) {
    auto known = frames.find(link.frame_id);
    if (known == frames.end()) known = frames.emplace(link.frame_id, lookup(link.frame_id)).first;
    const FrameTransform& frame = known->second;
    if (!frame.ok) {
      placed.error = "link '" + link.name + "': " + frame.error;
      return placed;
    }
    if (isStale(frame, freshness)) {
      placed.error =
          "link '" + link.name + "': its frame '" + link.frame_id + "' was last placed " +
          core::formatNumber(std::round(ageOf(frame, freshness) * 100) / 100) +
          " s ago, more than " + core::formatNumber(freshness.max_age_s) + " s (max_transform_age)";
      return placed;
    }
    const core::ProjectionResult result =
        placeInPlane(link, global_padding, frame.fixed_from_frame);
    if (!result.ok()) {
      placed.error = "link '" + link.name + "': " + result.error;
      return placed;
    }
    placed.links.push_back({link.name, core::EllipseRole::Link, result.ellipse});
    placed.stamp_s = std::max(placed.stamp_s, frame.stamp_s);
  }
  return placed;
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
    EllipseSpec spec = planarSpec(e, robot_name + "/" + link.name, frame);
    const auto before = last_.find(link.name);
    if (before != last_.end() && stamp_s == before->second.stamp_s) {
      // Nothing newer from tf: the same placement, the same motion as last said.
      spec.vx = before->second.vx;
      spec.vy = before->second.vy;
      spec.angular_velocity = before->second.angular_velocity;
    } else if (before != last_.end()) {
      const double dt = stamp_s - before->second.stamp_s;
      if (dt > 0.0 && dt <= kMaxIntervalS) {
        spec.vx = (e.center.x() - before->second.ellipse.center.x()) / dt;
        spec.vy = (e.center.y() - before->second.ellipse.center.y()) / dt;
        // Placed angles are reported in (-pi/2, pi/2] (an ellipse is the same after a half
        // turn): the turn is the shorter way round modulo pi, so a link turning through pi/2
        // turns by a little, not by almost -pi (an interval turns a link by less than pi/2).
        const double turn = std::remainder(e.angle - before->second.ellipse.angle, M_PI);
        spec.angular_velocity = turn / dt;
      }
    }
    now[link.name] = {stamp_s, e, spec.vx, spec.vy, spec.angular_velocity};
    footprint.push_back(spec);
  }
  last_ = std::move(now);
  return footprint;
}

}  // namespace ellipse_collision::app
