#include "demo_arm_guard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "demo_base_control.h"

namespace ellipse_collision {
namespace {

Pose2D compose(const Pose2D& a, const Pose2D& b) {
  const double c = std::cos(a.yaw), s = std::sin(a.yaw);
  Pose2D ab;
  ab.position = a.position + Eigen::Vector2d(c * b.position.x() - s * b.position.y(),
                                             s * b.position.x() + c * b.position.y());
  ab.yaw = a.yaw + b.yaw;
  return ab;
}

/// [m] farthest a point of the link can lie from the z axis through the origin of chain step
/// `first`, however the joints stand: the lengths of the later origins, the ellipse's centre and
/// its larger radius, end to end.
double reachFrom(const ArmLink& link, std::size_t first) {
  double sum = link.shape.center.norm() + core::boundingRadius(link.shape);
  for (std::size_t i = first + 1; i < link.chain.size(); ++i) {
    sum += link.chain[i].origin.position.norm();
  }
  return sum;
}

/// How far a point of `link` can move while time runs from t0_s to t1_s ahead [m]: its speed is
/// at most the base's speed, plus the base's turn rate times the reach from the base's origin,
/// plus each joint's rate times the reach from its axis.
double sweptDistance(const ArmLink& link, const std::vector<SineMotion>& joints, double arm_clock_s,
                     double direction, const core::Twist& base_twist, double t0_s, double t1_s) {
  const double base_reach =
      (link.chain.empty() ? 0.0 : link.chain.front().origin.position.norm()) + reachFrom(link, 0);
  double moved = std::abs(t1_s - t0_s) *
                 (std::hypot(base_twist.vx, base_twist.vy) + std::abs(base_twist.wz) * base_reach);
  for (std::size_t i = 0; i < link.chain.size(); ++i) {
    const int j = link.chain[i].joint;
    if (j >= 0)
      moved += joints[j].travel(arm_clock_s + direction * t0_s, arm_clock_s + direction * t1_s) *
               reachFrom(link, i);
  }
  return moved;
}

}  // namespace

Pose2D linkPose(const ArmLink& link, const std::vector<double>& q) {
  Pose2D pose;
  for (const ArmChainStep& step : link.chain) {
    pose = compose(pose, step.origin);
    if (step.joint >= 0) pose.yaw += step.axis * q[step.joint];
  }
  return pose;
}

core::Ellipse placedAt(const core::Ellipse& shape, const Pose2D& pose) {
  Pose2D centre;
  centre.position = shape.center;
  core::Ellipse placed = shape;
  placed.center = compose(pose, centre).position;
  placed.angle = shape.angle + pose.yaw;
  return placed;
}

std::vector<ArmSample> armSweep(const std::vector<ArmLink>& links,
                                const std::vector<SineMotion>& joints, double arm_clock_s,
                                double direction, const Pose2D& base, const core::Twist& base_twist,
                                const ArmGuardSettings& settings) {
  const int steps =
      std::max(1, static_cast<int>(std::ceil(settings.horizon_s / settings.step_s - 1e-9)));
  const double h = settings.horizon_s / steps;
  std::vector<ArmSample> sweep;
  std::vector<double> q(joints.size());
  for (int k = 0; k <= steps; ++k) {
    const double t = k * h;
    for (std::size_t j = 0; j < joints.size(); ++j)
      q[j] = joints[j].at(arm_clock_s + direction * t);
    const Pose2D base_then = poseAfterArc(base, base_twist, t);
    for (const ArmLink& link : links) {
      ArmSample sample;
      sample.name = link.name + "@" + std::to_string(k);
      sample.link = link.name;
      sample.time_s = t;
      sample.from_s = std::max(0.0, t - h / 2);
      sample.to_s = std::min(settings.horizon_s, t + h / 2);
      sample.ellipse = placedAt(link.shape, compose(base_then, linkPose(link, q)));
      sample.sweep_m = std::max(
          sweptDistance(link, joints, arm_clock_s, direction, base_twist, sample.from_s, t),
          sweptDistance(link, joints, arm_clock_s, direction, base_twist, t, sample.to_s));
      sweep.push_back(sample);
    }
  }
  return sweep;
}

std::optional<ArmHold> firstHold(const std::vector<ArmSample>& sweep,
                                 const std::vector<ArmContact>& contacts, double clearance_m) {
  std::map<std::string, const ArmSample*> by_name;
  for (const ArmSample& sample : sweep) by_name[sample.name] = &sample;
  std::optional<ArmHold> first;
  for (const ArmContact& contact : contacts) {
    const auto it = by_name.find(contact.query);
    if (it == by_name.end()) continue;
    const ArmSample& sample = *it->second;
    if (contact.distance_m > sample.sweep_m + clearance_m) continue;
    if (first && first->time_s <= sample.from_s) continue;
    first = ArmHold{sample.link, contact.obstacle, sample.from_s, sample.ellipse};
  }
  return first;
}

std::optional<ArmSample> undecidedSample(const std::vector<ArmSample>& sweep, double clearance_m,
                                         double warning_distance_m) {
  for (const ArmSample& sample : sweep) {
    if (sample.sweep_m + clearance_m >= warning_distance_m) return sample;
  }
  return std::nullopt;
}

std::string holdText(const ArmHold& hold, double clearance_m) {
  char when[32];
  if (hold.time_s < 0.005) {
    std::snprintf(when, sizeof(when), "now");
  } else {
    std::snprintf(when, sizeof(when), "in %.2f s", hold.time_s);
  }
  char near[48];
  if (clearance_m > 0.0) {
    std::snprintf(near, sizeof(near), "would come within %.2f m of", clearance_m);
  } else {
    std::snprintf(near, sizeof(near), "would touch");
  }
  return "arm held: " + hold.link + " " + near + " " + hold.obstacle + " " + when;
}

}  // namespace ellipse_collision
