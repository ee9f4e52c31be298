#include "rotating_pair.h"

#include "ellipse_collision/core/path_motion.h"

namespace ellipse_collision::core::detail {

RotatingPair rotatingPair(const Ellipse& a, const Eigen::Vector2d& a_velocity,
                          const Eigen::Vector2d& a_arc_velocity, double wa, const Ellipse& b,
                          const Motion& motion_b) {
  RotatingPair p{
      a, b, motion_b.velocity - a_velocity, wa, motion_b.angular_velocity, a_arc_velocity, {}};
  p.a.center = Eigen::Vector2d::Zero();
  using Long = long double;
  for (int i = 0; i < 2; ++i) {
    p.b.center[i] = split(Long(b.center[i]) - a.center[i], &p.low.b_center[i]);
    p.w[i] = split(Long(motion_b.velocity[i]) - a_velocity[i], &p.low.w[i]);
  }
  return p;
}

RotatingPair segmentPair(const Ellipse& link_in_moving, const SegmentMotion& motion,
                         const Ellipse& obstacle, const Motion& obstacle_motion) {
  // The link's centre moves on the line plus an arc about the frame's origin: the velocity
  // w z x R(start_yaw) c of that turn turns with the frame. The pair's start is computed in long
  // double, keeping what rounding leaves out (RotatingPair::low): far out, an ulp of the placed
  // centre (1e-14 m at 100 m) would be an error in every distance of a grazing pass.
  using Long = long double;
  const double w = motion.yaw_rate;
  const Long cos_yaw = std::cos(Long(motion.start_yaw)), sin_yaw = std::sin(Long(motion.start_yaw));
  const Long arm_x = cos_yaw * link_in_moving.center.x() - sin_yaw * link_in_moving.center.y();
  const Long arm_y = sin_yaw * link_in_moving.center.x() + cos_yaw * link_in_moving.center.y();
  // The relative velocity from rotatingPair(); the relative centre and a's angle from here.
  RotatingPair pair = rotatingPair(link_in_moving, motion.velocity, Eigen::Vector2d::Zero(), w,
                                   obstacle, obstacle_motion);
  RotatingPair::LowParts& low = pair.low;
  pair.a_arc_velocity = {split(-w * arm_y, &low.a_arc_velocity.x()),
                         split(w * arm_x, &low.a_arc_velocity.y())};
  pair.b.center = {split(Long(obstacle.center.x()) - motion.start.x() - arm_x, &low.b_center.x()),
                   split(Long(obstacle.center.y()) - motion.start.y() - arm_y, &low.b_center.y())};
  pair.a.angle = split(Long(link_in_moving.angle) + motion.start_yaw, &low.a_angle);
  return pair;
}

}  // namespace ellipse_collision::core::detail
