#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/path_check.h"
#include "ellipse_collision/core/path_motion.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core {

// A velocity gate: before a planar velocity command is sent, predict where the robot's links
// would first touch an obstacle if the command were held, and pass, scale down or stop it.
// Everything is expressed in the robot frame as it is at t = 0 (an inertial frame for the
// horizon): links at their pose at t = 0, obstacles where they are at t = 0 with their Motion.

/// A planar velocity command in the robot frame, held constant: the robot frame then follows
/// exp(t * twist), an arc about the instantaneous centre of rotation (a line when wz = 0).
struct Twist {
  double vx{0.0};  ///< velocity of the frame's origin along its x axis [m/s]
  double vy{0.0};  ///< along its y axis [m/s]
  double wz{0.0};  ///< counter-clockwise turn rate [rad/s]
};

/// `twist` scaled by `k` (every component).
Twist scaled(const Twist& twist, double k);

/// The robot frame's pose after `t` [s] of `twist`, in the frame at t = 0 (time = t):
/// x + i y = (vx + i vy) (e^{i wz t} - 1) / (i wz), evaluated as t sinc(wz t) and
/// t sin(wz t / 2) sinc(wz t / 2) (= (1 - cos(wz t)) / wz) so that a tiny wz, or a far
/// instantaneous centre, loses no precision (no 1 - cos, no division by wz).
PathPose poseAfter(const Twist& twist, double t);

/// A link (in the robot frame at t = 0) after `t` [s] of `twist`.
Ellipse linkAfter(const Ellipse& link, const Twist& twist, double t);

/// Every link after `t` [s] of `twist`, names and roles kept: the robot drawn at a predicted
/// contact.
std::vector<NamedEllipse> linksAtTime(const std::vector<NamedEllipse>& links, const Twist& twist,
                                      double t);

/// Why `twist` cannot be held over `horizon` (finite, >= 0), naming the field and value
/// ("twist.vx = nan must be finite", "twist.wz = 50 turns more than 100 rad within horizon = 3
/// s"), or "": firstContact()'s velocity limits (invalidVelocityReason()) under the names
/// twist.vx, twist.vy, twist.wz.
std::string invalidTwistReason(const Twist& twist, double horizon);

/// Why twistContact() cannot be called with these arguments, naming the part, field and value
/// ("link: radius_x = 0 must be > 0", "obstacle: velocity.y = inf must be finite"), or "":
/// either ellipse invalid, the horizon negative or not finite, the twist (invalidTwistReason()),
/// the obstacle's motion (invalidMotionReason()), or the link able to leave kMaxCoordinate
/// within the horizon (|centre| + R + |(vx, vy)| horizon, the arc being no longer than the line).
std::string invalidTwistContactReason(const Ellipse& link, const Twist& twist,
                                      const Ellipse& obstacle, const Motion& obstacle_motion,
                                      double horizon);

/// The first time in [0, horizon] [s] at which `link`, rigidly attached to the robot frame moving
/// by `twist`, touches `obstacle` moving by `obstacle_motion` (overlap(): containment and a shared
/// boundary point count). Overlap at t = 0 gives {true, 0}; a pair apart at 0 never gets time 0.
///  - wz == 0: the link moves by the Motion {(vx, vy), 0} and firstContact() answers: exact when
///    the obstacle does not turn (a turning circle does not), certified never late otherwise.
///  - wz != 0: the link's centre moves on an arc about the instantaneous centre; firstContact()'s
///    rotating method (rotating_contact.cpp: conservative advancement on the exact distance(),
///    each step the larger of D / V and the root of a second-order Taylor bound of the separation
///    along the witness direction), certified never late, with
///      |D'| <= V = max over s in [0, horizon] of |v_o - R(wz s) v_c| + |wz| (R_l - r_l)
///              + |w_o| (R_o - r_o),   v_c = (vx, vy) + wz z x c_l,
///    v_c being the link centre's velocity in the robot frame (constant: the frame turns with it,
///    so the link centre moves at the constant speed |v_c|), v_o the obstacle's velocity, and
///    |wz| (R - r) the largest rate of a support function of an ellipse turning about its centre
///    (Mirtich 1996; Zhang, Lee, Kim, Manocha 2006); the first term is |v_o| + |v_c| only when the
///    turn brings v_c against v_o, otherwise its value at an end of the turn. The second-order
///    bound adds the centre's centripetal acceleration |wz| |v_c| to the sweep curvature of the
///    ellipses. As in firstContact(), within 2.5e-10 * horizon of the first contact (tested
///    against a quad oracle of the arc on passes grazing 1e-8 to 1e-12 deep), a tangency within
///    5e-10 relative of grazing reported in contact; a safety cap of 20000 steps, never reached
///    on the tests and the benchmark, would report contact at the last certified-safe time.
/// Precondition: invalidTwistContactReason() is empty (otherwise unspecified, but it returns).
FirstContact twistContact(const Ellipse& link, const Twist& twist, const Ellipse& obstacle,
                          const Motion& obstacle_motion, double horizon);

/// The gate's parameters. Accepted: every value finite, horizon > 0,
/// 0 <= stop_time <= time_before_collision <= horizon, margin >= 0, 0 < resolution <= 1.
struct GateSettings {
  double horizon{3.0};                ///< how far ahead contacts are predicted [s]
  double time_before_collision{1.5};  ///< the command is scaled so no contact comes sooner [s]
  double stop_time{0.3};              ///< a contact this soon under the full command stops [s]
  double margin{0.05};                ///< pairs closer than this now are "close" (escape rule) [m]
  double resolution{0.01};            ///< grid of the scale factor: k in {0, res, 2 res, ..., 1}
};

/// What the gate does with the command.
enum class GateAction {
  Pass,    ///< sent as given (scale 1)
  Slow,    ///< scaled by 0 < scale < 1
  Stop,    ///< scale 0
  Escape,  ///< some pair is close now; the command (scaled by 0 < scale <= 1) moves them apart
};

/// "pass", "slow", "stop", "escape".
const char* toString(GateAction action);

/// A predicted contact of one link with one obstacle.
struct GateContact {
  bool found{false};
  std::string link;
  std::string obstacle;
  double time{0.0};   ///< [s] after t = 0 under scale * twist
  double scale{1.0};  ///< of the command this contact is predicted under
  /// Where they touch at `time`, in the frame of the scene at t = 0 [m]: the midpoint of the
  /// witness points (of the pair shrunk to just below contactScale() when they touch or overlap).
  Eigen::Vector2d point{0.0, 0.0};
};

/// The answer of gateCommand().
struct GateResult {
  GateAction action{GateAction::Stop};
  double scale{0.0};  ///< send scale * twist; in [0, 1]
  /// The first contact within the horizon under the output command (scale * twist); for Stop,
  /// that of a moving obstacle reaching the standing robot (stopping cannot avoid it).
  GateContact contact;
  /// The contact that decided the scale: the first contact under the full command (Pass, Slow
  /// and Stop with standing obstacles), the contact that ruled out the next larger scale (moving
  /// obstacles), or the close pair the command pushes in (time 0).
  GateContact limiting;
  /// The nearest pair now among those that can meet within the horizon (the broadphase's
  /// candidates); has_clearance false when there is none.
  bool has_clearance{false};
  double clearance{0.0};  ///< distance() now [m]; 0 when overlapping
  std::string clearance_link;
  std::string clearance_obstacle;
  std::string reason;  ///< why, in words, with names, times and scales
  std::string error;   ///< why the command could not be judged (then action Stop, scale 0)
  /// distance() and twistContact() calls: a statistic for tests and benchmarks.
  std::size_t pair_tests{0};
  bool ok() const { return error.empty(); }
};

/// Why gateCommand() cannot judge `twist` in `scene`, naming the field and value ("settings:
/// stop_time = 2 must be <= time_before_collision = 1.5", "obstacle 'wall': radius_x = 0 must be
/// > 0", "twist.vx = inf must be finite"), or "": settings out of their ranges (GateSettings),
/// the twist (invalidTwistReason()), obstacle_motions not one per obstacle, an empty or duplicate
/// name among the links or among the obstacles, a link failing invalidTwistContactReason()'s
/// rules, an obstacle whose ellipse or motion over the horizon is invalid (invalidMotionReason()).
/// Its cost grows with the obstacles: validate a scene once when it changes.
std::string invalidGateReason(const PathScene& scene, const Twist& twist,
                              const GateSettings& settings);

/// Gates `twist` for the links of `scene` (in the robot frame at t = 0) against its obstacles (in
/// that frame, each moving by its Motion), for every link-obstacle pair not in scene.allowed.
///
/// Rules (T_b = time_before_collision, T_s = stop_time, H = horizon, k the scale):
///  1. Close pairs: distance() now; a pair overlapping or closer than margin is close.
///  2. Close pairs present -> the escape rule. For each close pair the robot's own contribution
///     to the distance's rate at t = 0 is -n . (v + wz z x p_l), with p_l the link's witness
///     point and n the unit direction from it to the obstacle's (for an overlapping or touching
///     pair, those of the pair shrunk about their centres to just below their contactScale():
///     the Perram-Wertheim contact point and normal). If it is negative (beyond rounding) for any
///     close pair: Stop, "pushes into '<obstacle>'". The obstacle's own contribution is not
///     judged: stopping cannot undo it. Otherwise the contact rule (3) runs on every pair not
///     overlapping now (separated close pairs included), and the action is Escape with its scale
///     (Stop when it gives 0).
///  3. Contact rule, first contacts by twistContact() (never late):
///     t_1 = the first contact under the full command over [0, H], all pairs.
///     - t_1 <= T_s: Stop.
///     - Standing obstacles (no velocity; no spin, or a circle): under k twist the robot traces
///       the same arc k times slower, so their first contact is at t_s / k, t_s their first
///       contact at k = 1, solved once. The largest grid k with t_s / k >= T_b caps k (1 when
///       t_s >= T_b or none).
///     - Moving obstacles: searched, not guessed: k runs down the grid from that cap and the
///       first k whose twistContact() under k twist finds no moving pair touching before T_b is
///       taken.
///     - k = 1: Pass ("no contact within time_before_collision under the full command"); 0 < k <
///       1: Slow; no k > 0 on the grid: Stop. With k = 0 the standing robot is checked against
///       the moving obstacles too; a hit is reported in `contact` and the reason (unavoidable by
///       stopping), the action stays Stop.
/// Broadphase, allocation-free per obstacle: link l stays in the disc about its centre c_l of
/// radius |v_c| H + R_l for every k in [0, 1] (its centre moves at the constant speed k |v_c|),
/// an obstacle in the capsule of radius R_o about the segment its centre sweeps; pairs whose
/// disc and capsule (grown by margin) are apart are never looked at, and obstacles outside the
/// disc about the origin containing every link's cost one segment-distance test.
/// Search, the same answers for less work: a pair cannot be reported in contact under k twist
/// before its bounding circles' gap now (less twistContact()'s grazing band) over k |v_c| + |v_o|,
/// the fastest they can close, less the resolution of twistContact() (2.5e-10 of the horizon);
/// the first contacts are found pair by pair, roughly soonest bound
/// first, each pair searched only up to the earliest contact kept so far (the advancement's
/// steps are those of the horizon, stopped early, so the earliest keeps its time) and not at all
/// when its bound is later; moving pairs under the full command only up to the standing pairs'
/// first contact (a later one decides nothing and is not the first); in the search over k, pairs
/// whose bound is not before T_b are not tried. Actions, scales and times are those of every pair
/// searched over the horizon; only a pair stopped at the advancement's safety cap on the steps
/// (never reached on the tests) could be passed over for a later claim, which is then still never
/// later than the motion's first contact.
/// Inputs: the twist, the settings, the links and the obstacle_motions count are checked on
/// every call (an error names them, the action is Stop); an obstacle is checked only when it
/// passes the broadphase, where a non-finite one always does (invalidGateReason() checks all).
GateResult gateCommand(const PathScene& scene, const Twist& twist, const GateSettings& settings);

}  // namespace ellipse_collision::core
