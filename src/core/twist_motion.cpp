#include "ellipse_collision/core/twist_motion.h"

#include "arc_motion.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/overlap.h"
#include "twist_motion_detail.h"

namespace ellipse_collision::core {
namespace detail {

RotatingPair twistPair(const Ellipse& link, const Twist& twist, const Ellipse& obstacle,
                       const Motion& obstacle_motion) {
  RotatingPair pair = rotatingPair(link, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), twist.wz,
                                   obstacle, obstacle_motion);
  // The link's centre moves on an arc: its whole velocity v + wz z x c turns with the frame.
  using Long = long double;
  Eigen::Vector2d& low = pair.low.a_arc_velocity;
  pair.a_arc_velocity = {split(Long(twist.vx) - Long(twist.wz) * link.center.y(), &low.x()),
                         split(Long(twist.vy) + Long(twist.wz) * link.center.x(), &low.y())};
  return pair;
}

FirstContact twistContactUntil(const Ellipse& link, const Twist& twist, const Ellipse& obstacle,
                               const Motion& obstacle_motion, double horizon, double until) {
  if (twist.wz == 0.0) {
    // The frame does not turn: the link translates by (vx, vy), a Motion of the core.
    const FirstContact contact =
        firstContact(link, Motion{{twist.vx, twist.vy}, 0.0}, obstacle, obstacle_motion, horizon);
    return contact.contact && contact.time <= until ? contact : FirstContact{};
  }
  if (overlap(link, obstacle)) return {true, 0.0};
  if (!(horizon > 0.0)) return {};
  // Apart at t = 0 (overlap() above): time 0 is for pairs that overlap now.
  return apartAtZero(
      rotatingContact(twistPair(link, twist, obstacle, obstacle_motion), horizon, nullptr, until),
      horizon);
}

std::string linkReachReason(const Ellipse& link, const Twist& twist, double horizon) {
  const double reach = link.center.norm() + boundingRadius(link) +
                       Eigen::Vector2d(twist.vx, twist.vy).norm() * horizon;
  if (!(reach <= kMaxCoordinate)) {
    return "reaches " + formatNumber(reach) +
           " m from the origin within horizon = " + formatNumber(horizon) + " s, beyond " +
           formatNumber(kMaxCoordinate) + " m";
  }
  return {};
}

}  // namespace detail

Twist scaled(const Twist& twist, double k) { return {k * twist.vx, k * twist.vy, k * twist.wz}; }

PathPose poseAfter(const Twist& twist, double t) {
  const detail::Displacement<double> moved =
      detail::arcDisplacement(twist.vx, twist.vy, twist.wz, t);
  return {moved.x, moved.y, twist.wz * t, t};
}

Ellipse linkAfter(const Ellipse& link, const Twist& twist, double t) {
  const PathPose pose = poseAfter(twist, t);
  return placeAt(link, {pose.x, pose.y}, pose.yaw);
}

std::vector<NamedEllipse> linksAtTime(const std::vector<NamedEllipse>& links, const Twist& twist,
                                      double t) {
  const PathPose pose = poseAfter(twist, t);
  std::vector<NamedEllipse> placed = links;
  for (NamedEllipse& link : placed)
    link.ellipse = placeAt(link.ellipse, {pose.x, pose.y}, pose.yaw);
  return placed;
}

std::string invalidTwistReason(const Twist& twist, double horizon) {
  return invalidVelocityReason(Motion{{twist.vx, twist.vy}, twist.wz}, horizon,
                               {"twist.vx", "twist.vy", "twist.wz"});
}

std::string invalidTwistContactReason(const Ellipse& link, const Twist& twist,
                                      const Ellipse& obstacle, const Motion& obstacle_motion,
                                      double horizon) {
  if (std::string r = invalidReason(link); !r.empty()) return "link: " + r;
  if (std::string r = invalidReason(obstacle); !r.empty()) return "obstacle: " + r;
  if (!std::isfinite(horizon)) return "horizon = " + formatNumber(horizon) + " must be finite";
  if (horizon < 0.0) return "horizon = " + formatNumber(horizon) + " must be >= 0";
  if (std::string r = invalidTwistReason(twist, horizon); !r.empty()) return r;
  if (std::string r = detail::linkReachReason(link, twist, horizon); !r.empty()) {
    return "link: " + r;
  }
  if (std::string r = invalidMotionReason(obstacle, obstacle_motion, horizon); !r.empty()) {
    return "obstacle: " + r;
  }
  return {};
}

FirstContact twistContact(const Ellipse& link, const Twist& twist, const Ellipse& obstacle,
                          const Motion& obstacle_motion, double horizon) {
  return detail::twistContactUntil(link, twist, obstacle, obstacle_motion, horizon, horizon);
}

}  // namespace ellipse_collision::core
