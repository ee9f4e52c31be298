#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// Rigid planar motion of an ellipse over a time horizon: centre(t) = center + velocity t,
/// angle(t) = angle + angular_velocity t.
struct Motion {
  Eigen::Vector2d velocity{0.0, 0.0};  ///< [m/s]
  double angular_velocity{0.0};        ///< about the ellipse's centre, counter-clockwise [rad/s]
};

/// The first time two moving ellipses share a point, if any within the horizon.
struct FirstContact {
  bool contact{false};  ///< the closed ellipses share a point at some t in [0, horizon]
  double time{0.0};     ///< first such t [s], in [0, horizon]; 0 when contact is false
};

/// Largest speed per velocity component accepted [m/s].
constexpr double kMaxSpeed = 1e9;
/// Largest |angular_velocity| accepted [rad/s].
constexpr double kMaxAngularVelocity = 1e9;
/// Largest |angular_velocity| * horizon accepted [rad] (about 16 turns): it bounds the work of the
/// conservative advancement used for rotating pairs (doc/rotating_contact.md).
constexpr double kMaxTurn = 100.0;

/// How far across itself double precision may move a translating pair's path, relative to the
/// pair's extent along and across it (see firstContact()): about 1.4e-14.
constexpr double kTranslationExtentTolerance = 64.0 * std::numeric_limits<double>::epsilon();

/// Why (a, motion_a, b, motion_b, horizon) cannot be given to firstContact(), naming the field and
/// value ("ellipse 2: radius_x = -1 must be > 0", "motion 1: angular_velocity = nan must be
/// finite", "horizon = -1 must be >= 0"), or "" when it can. Refused: an invalid ellipse (see
/// invalidReason()); a velocity component not finite or beyond kMaxSpeed; an angular velocity not
/// finite or beyond kMaxAngularVelocity; a horizon negative or not finite; |angular_velocity| *
/// horizon > kMaxTurn; a centre that leaves [-kMaxCoordinate, kMaxCoordinate] within the horizon.
/// Within these bounds no intermediate quantity of firstContact() can overflow or become NaN.
std::string invalidMotionReason(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                                const Motion& motion_b, double horizon);

/// How a message names the three fields of a velocity.
struct VelocityFieldNames {
  const char* x{"velocity.x"};
  const char* y{"velocity.y"};
  const char* angular{"angular_velocity"};
};

/// Why a rigid velocity breaks the limits above over `horizon` (finite, >= 0), naming the field as
/// `names` gives it ("velocity.x = nan must be finite"), or "": a component not finite or beyond
/// kMaxSpeed, an angular velocity not finite or beyond kMaxAngularVelocity, or more than kMaxTurn
/// turned within the horizon. The one rule for obstacle motions and robot commands
/// (velocity_gate.h).
std::string invalidVelocityReason(const Motion& motion, double horizon,
                                  const VelocityFieldNames& names = {});

/// The part of invalidMotionReason() that concerns one ellipse and its motion over `horizon`
/// (finite, >= 0), with no "ellipse 1: " / "motion 1: " prefix: the ellipse's fields, its velocity
/// (invalidVelocityReason()) and its centre staying within kMaxCoordinate over the horizon.
std::string invalidMotionReason(const Ellipse& ellipse, const Motion& motion, double horizon);

/// The first time t in [0, horizon] [s] at which `a` and `b`, each moving rigidly by its motion,
/// overlap (per overlap(): a shared boundary point or containment counts); overlap at t = 0 gives
/// {true, 0}. Translation: exact up to rounding, early by at most kTranslationExtentTolerance
/// times the pair's extent over (|relative velocity| cos theta), theta the path's angle to the
/// Minkowski sum's normal at the entry. Rotation: never late, at most 2.5e-10 * horizon early
/// where the pair overlaps (a pair grazing within 1e-9 may be reported in contact). Exactly
/// symmetric in (a, motion_a) and (b, motion_b). The verdict is settled where the search can
/// settle it: a path stopping short of a needle's flat side (axis ratio up to 1e18) by more than
/// kTranslationExtentTolerance times the entry's distance from its centre is clear. Accuracy and
/// method: doc/core_methods.md.
/// Precondition: invalidMotionReason(a, motion_a, b, motion_b, horizon) is empty; otherwise the
/// result is unspecified (but the call returns).
FirstContact firstContact(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                          const Motion& motion_b, double horizon);

}  // namespace ellipse_collision::core
