#include "ellipse_collision/core/path_motion.h"

#include <algorithm>
#include <cmath>

#include "ellipse_collision/core/overlap.h"
#include "rotating_contact.h"

namespace ellipse_collision::core {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Relative widening of swept boxes, as boundingCircleBox(): rounding never separates the boxes of
// ellipses that touch.
constexpr double kBoxWidening = 1e-12;

Eigen::Vector2d rotated(const Eigen::Vector2d& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

BoundingBox circleBox(const Eigen::Vector2d& centre, double radius) {
  const double r = radius * (1.0 + kBoxWidening) + kBoxWidening * centre.cwiseAbs().maxCoeff();
  return {centre.x() - r, centre.y() - r, centre.x() + r, centre.y() + r};
}

BoundingBox unite(const BoundingBox& a, const BoundingBox& b, double grow) {
  return {std::min(a.min_x, b.min_x) - grow, std::min(a.min_y, b.min_y) - grow,
          std::max(a.max_x, b.max_x) + grow, std::max(a.max_y, b.max_y) + grow};
}

FirstContact contactAt(double t) { return {true, t}; }

}  // namespace

double shortestRotation(double from_yaw, double to_yaw) {
  double d = std::remainder(to_yaw - from_yaw, 2.0 * kPi);  // in [-pi, pi]
  return d;
}

SegmentMotion segmentMotion(const PathPose& from, const PathPose& to, double duration) {
  SegmentMotion m;
  m.start = {from.x, from.y};
  m.duration = duration;
  m.velocity = Eigen::Vector2d(to.x - from.x, to.y - from.y) / duration;
  m.start_yaw = from.yaw;
  m.yaw_rate = shortestRotation(from.yaw, to.yaw) / duration;
  return m;
}

Ellipse placeAt(const Ellipse& in_moving, const Eigen::Vector2d& position, double yaw) {
  Ellipse e = in_moving;
  e.center = position + rotated(in_moving.center, yaw);
  e.angle = in_moving.angle + yaw;
  return e;
}

Ellipse movedBy(const Ellipse& e, const Motion& motion, double tau) {
  Ellipse moved = e;
  moved.center = e.center + motion.velocity * tau;
  moved.angle = e.angle + motion.angular_velocity * tau;
  return moved;
}

BoundingBox sweptBox(const Ellipse& e, const Motion& motion, double horizon) {
  const double r = boundingRadius(e);
  return unite(circleBox(e.center, r), circleBox(e.center + motion.velocity * horizon, r), 0.0);
}

BoundingBox sweptLinkBox(const Ellipse& link_in_moving, const SegmentMotion& motion) {
  const double turn = motion.yaw_rate * motion.duration;
  const Ellipse at_start = placeAt(link_in_moving, motion.start, motion.start_yaw);
  const Ellipse at_end = placeAt(link_in_moving, motion.start + motion.velocity * motion.duration,
                                 motion.start_yaw + turn);
  const double sagitta = link_in_moving.center.norm() * (1.0 - std::cos(0.5 * turn));
  const double r = boundingRadius(link_in_moving);
  return unite(circleBox(at_start.center, r), circleBox(at_end.center, r),
               sagitta * (1.0 + kBoxWidening));
}

std::string invalidSegmentReason(const Ellipse& obstacle, const Motion& obstacle_motion,
                                 double duration) {
  // The link's own motion stays within the path's poses, which the caller has validated.
  return invalidMotionReason(obstacle, obstacle_motion, obstacle, Motion{}, duration);
}

FirstContact segmentContact(const Ellipse& link_in_moving, const SegmentMotion& motion,
                            const Ellipse& obstacle, const Motion& obstacle_motion) {
  const Ellipse link_start = placeAt(link_in_moving, motion.start, motion.start_yaw);
  const bool offset = link_in_moving.center.x() != 0.0 || link_in_moving.center.y() != 0.0;
  if (!offset || motion.yaw_rate == 0.0) {
    // The centre moves on the line: a Motion of the core describes the link exactly.
    return firstContact(link_start, Motion{motion.velocity, motion.yaw_rate}, obstacle,
                        obstacle_motion, motion.duration);
  }
  if (overlap(link_start, obstacle)) return contactAt(0.0);
  return detail::apartAtZero(
      detail::rotatingContact(
          detail::segmentPair(link_in_moving, motion, obstacle, obstacle_motion), motion.duration),
      motion.duration);
}

}  // namespace ellipse_collision::core
