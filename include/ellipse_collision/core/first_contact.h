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
/// conservative advancement used for rotating pairs (see rotating_contact.cpp).
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
/// overlap (per overlap(): a shared boundary point or containment counts). Overlap at t = 0 gives
/// {true, 0}.
///  - Pure translation (both angular velocities 0): exact, where the relative path enters the
///    Minkowski sum K of the two ellipses (one safeguarded root on the sum's normal angle,
///    certified from both sides), up to rounding: the time is that of the path moved across itself
///    by at most kTranslationExtentTolerance * E, E = |p0 . d| + h_K(n) [m]. So it is earlier than
///    the true crossing by at most kTranslationExtentTolerance * E / (|w| cos theta) [s], later by
///    at most 8 eps E / (|w| cos theta) (rounding, not a margin): w the relative velocity, d its
///    direction, n = d turned +90 deg, p0 = b.center - a.center, h_K(n) = h_A(n) + h_B(n) the
///    half-width of K across the path (h_E(n) = |(radius_x (n . e_x), radius_y (n . e_y))|),
///    theta the angle between the path and K's outer normal at the entry (0 head-on). The
///    1 / cos theta is the problem's conditioning, not the method's: moving the path across itself
///    moves the entry along it tan theta times as far, and double precision places the path
///    relative to K only to ~eps E (the relative centre, the path's direction and the ellipses'
///    sin and cos are rounded; one ulp of a centre moves the exact entry of a path at
///    cos theta = 4.5e-4 by 7.8 times the head-on bound, test_first_contact). Head-on, for pairs of
///    comparable size and distance, this is ~1e-14 of the time to cross the pair (within ~1e-12 *
///    horizon on the tests); cos theta is small for a path that nearly grazes K or moves nearly
///    along a needle's flat side, and a short path across the flat side of a needle of axis ratio
///    1e14 can be early by a large share of the horizon, but not by more than this bound (tested
///    against the quad oracle: needles of axis ratios to 1e18 crossed, at most 0.08 of it early,
///    0.03 late; specks against ellipses to 1e3 m and needles to 1e6 m at 1e-4..0.1 m/s, grazing
///    and along flat sides down to cos theta = 1e-8, at most 0.04 of it). The verdict, contact
///    within the horizon or not, is not left to that bound where the search can settle it: the
///    search goes on while the entry's bracket, its roundings included, holds p0 or the horizon's
///    reach, near a needle's flat side in the needle's own frame. So a path that stops short of the
///    flat side of a needle of axis ratio up to 1e18 by more than kTranslationExtentTolerance times
///    the entry point's distance from the needle's centre is clear, however long the needle
///    (tested against the quad gauge: 270 paths at up to 70 deg to the side's normal, near its
///    centre or anywhere along it, 201 stopping 5..95 % of the way, 69 going 5..200 % past it).
///  - Rotation: certified, never late (conservative advancement on the exact distance(), each step
///    the larger of D / V and the root of a second-order Taylor bound of the separation along the
///    witness direction); never `clear` for a pair that touches (outside a 1e-9 band around
///    grazing). The steps stop once overlap() confirms a contact 2.5e-10 * horizon ahead, so
///    the time is within that of the first contact (tested within 1e-9 of the horizon of the quad
///    oracle, touching passes grazing 1e-8 to 1e-12 deep included: within ~1e-13 of the radii of
///    a tangency the separation is evaluated in long double); inside the band a pair that only
///    grazes may be reported in contact, its time unresolved. A grazing pass costs a few steps,
///    not sqrt(size / gap) of them: at most 54 distance() calls per pair on the benchmark's mix
///    for axis ratios to 100, 200 on the tests' passes grazing 1e-12 deep, growing about as the
///    square root of the axis ratio (929 at 1e4). A safety cap of 20000 steps, never reached
///    there, would report contact at the last certified-safe time. Spinning circles count as
///    translating.
/// Exactly symmetric: swapping (a, motion_a) with (b, motion_b) gives the same bits.
/// Precondition: invalidMotionReason(a, motion_a, b, motion_b, horizon) is empty; otherwise the
/// result is unspecified (but the call returns).
FirstContact firstContact(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                          const Motion& motion_b, double horizon);

}  // namespace ellipse_collision::core
