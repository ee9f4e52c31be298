#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ellipse_collision {

/// offset + amplitude * sin(2 pi t / period_s + phase): one joint's sweep [rad].
struct SineMotion {
  double offset{0.0};     ///< [rad]
  double amplitude{0.0};  ///< [rad]
  double period_s{1.0};   ///< [s], > 0
  double phase{0.0};      ///< [rad]
  double at(double t_s) const;
  /// How far the joint turns between t0_s and t1_s, back and forth counted alike [rad]: the
  /// integral of |d at / dt| (t0_s > t1_s is the same stretch).
  double travel(double t0_s, double t1_s) const;
};

/// A planar pose: position [m] and heading [rad] in the odometry frame.
struct Pose2D {
  Eigen::Vector2d position{0.0, 0.0};
  double yaw{0.0};
};

/// Back and forth between two points with a smooth (cosine) speed profile, at `start` for t = 0.
struct ShuttleMotion {
  Eigen::Vector2d start{0.0, 0.0};  ///< [m]
  Eigen::Vector2d end{0.0, 0.0};    ///< [m]
  double period_s{1.0};             ///< there and back [s], > 0
  Eigen::Vector2d at(double t_s) const;
};

struct NamedJointMotion {
  std::string joint;  ///< URDF joint name
  SineMotion motion;
};

/// The joints the demo driver moves by the clock, as a function of the demo's own clock (which
/// stops while the driver is paused). The base is not here: it moves by the velocity gate's output
/// (demo_base_control.h); nor the moving obstacle: it is part of the world (demo_world.h).
struct DemoTrajectory {
  std::vector<NamedJointMotion> joints;
};

}  // namespace ellipse_collision
