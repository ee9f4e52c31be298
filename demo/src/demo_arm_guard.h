#pragma once

#include <optional>
#include <string>
#include <vector>

#include "demo_trajectory.h"
#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/velocity_gate.h"

namespace ellipse_collision {

/// The demo arm's guard, without ROS: before the driver moves the arm's joints on along their
/// sweep it samples the links' next motion, asks the collision node how near each sampled link
/// is to the obstacles (~check_collisions with the samples as query ellipses), and holds the
/// joints while a link would come within `clearance_m` of one. doc/demo.md explains the rule.

/// One joint on the way from the base frame to a link of a planar arm (every joint turns about
/// z, every origin turns about z only).
struct ArmChainStep {
  Pose2D origin;  ///< the joint's frame in its parent link's frame at joint value 0 [m, rad]
  int joint{-1};  ///< index of the driven joint that turns it (DemoTrajectory::joints); -1: fixed
  double axis{1.0};  ///< +1: a rising joint value turns it counter-clockwise about z; -1: clockwise
};

/// A link the guard watches: its ellipse in its own frame and the chain from the base to it.
struct ArmLink {
  std::string name;
  core::Ellipse shape;  ///< in the link's frame [m], padded as the collision node pads it
  std::vector<ArmChainStep> chain;  ///< the base frame's child first
};

/// The link's frame in the base frame at the driven joints' values `q` [rad].
Pose2D linkPose(const ArmLink& link, const std::vector<double>& q);

/// `shape` (in a frame) placed in the frame where that frame's pose is `pose`.
core::Ellipse placedAt(const core::Ellipse& shape, const Pose2D& pose);

/// How far ahead the guard looks, and how close it lets the arm come.
struct ArmGuardSettings {
  double horizon_s{0.3};     ///< the motion checked ahead [s], > 0
  double step_s{0.05};       ///< at most this between sampled poses [s], in (0, horizon_s]
  double clearance_m{0.05};  ///< the joints hold when a link would come this close [m], >= 0
  /// After holding this long for an obstacle [s] the arm backs off along its sweep, for up to
  /// retreat_s of it [s] while that way is clear, then goes on.
  double retreat_after_s{1.0};
  double retreat_s{2.0};
};

/// One sampled pose of one link.
struct ArmSample {
  std::string name;  ///< unique query name: "<link>@<sample index>"
  std::string link;
  double time_s{0.0};  ///< how far ahead [s]
  double from_s{0.0};  ///< the stretch of the motion the sample stands for [s]: [from_s, to_s]
  double to_s{0.0};
  core::Ellipse ellipse;  ///< the link at time_s, in the frame of the base's pose (odom)
  /// Farthest any point of the link moves within [from_s, to_s] from where it is at time_s [m]:
  /// the base's speed and turn plus each joint's travel times its reach, a bound that holds
  /// however the joints stand.
  double sweep_m{0.0};
};

/// The next `settings.horizon_s` of the arm's motion, sampled at equal steps of at most
/// `settings.step_s` (0 and horizon_s included): the joints along `joints` from `arm_clock_s` on
/// (`direction` +1) or back along them (-1: the arm retracing its sweep), the base along the arc
/// of `base_twist` from `base`. Samples in time order, links in order.
std::vector<ArmSample> armSweep(const std::vector<ArmLink>& links,
                                const std::vector<SineMotion>& joints, double arm_clock_s,
                                double direction, const Pose2D& base, const core::Twist& base_twist,
                                const ArmGuardSettings& settings);

/// A sampled link near an obstacle, as the check answered: a collision (distance 0) or a warning
/// pair with its distance [m].
struct ArmContact {
  std::string query;  ///< ArmSample::name
  std::string obstacle;
  double distance_m{0.0};
};

/// Why the joints hold: the soonest sample that comes within its sweep plus the clearance of an
/// obstacle.
struct ArmHold {
  std::string link;
  std::string obstacle;
  double time_s{0.0};     ///< the earliest the link may come that close [s] (the sample's from_s)
  core::Ellipse ellipse;  ///< the link at that sample, for the marker
};

/// The hold rule: the sample of least from_s among `contacts` whose distance is at most its
/// sweep_m + clearance_m, or nothing (the joints may move on). Contacts naming no sample of
/// `sweep` are ignored.
std::optional<ArmHold> firstHold(const std::vector<ArmSample>& sweep,
                                 const std::vector<ArmContact>& contacts, double clearance_m);

/// The check reports pairs only within `warning_distance_m`: a sample whose sweep_m plus
/// `clearance_m` reaches that far could be too near without being reported. The first such
/// sample, or nothing when the answer decides every sample.
std::optional<ArmSample> undecidedSample(const std::vector<ArmSample>& sweep, double clearance_m,
                                         double warning_distance_m);

/// "arm held: forearm would come within 0.05 m of scan_120 in 0.25 s" ("would touch" for a
/// clearance of 0; "now" for a time under 5 ms).
std::string holdText(const ArmHold& hold, double clearance_m);

}  // namespace ellipse_collision
