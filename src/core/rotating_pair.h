#pragma once

// The pair that rotatingContact() (rotating_contact.h) steps: two ellipses in the frame of a's
// centre, and how firstContact(), segmentContact() and twistContact() build it. Internal to the
// core (src/core).

#include <Eigen/Core>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"
#include "arc_motion.h"
#include "sin_cos.h"

namespace ellipse_collision::core {
struct SegmentMotion;
}  // namespace ellipse_collision::core

namespace ellipse_collision::core::detail {

/// A pair in the frame of a's centre at t = 0, so that centres 1e6 m out lose no precision: `a`
/// turning at `wa` about its centre, which stays at the origin, and `b` turning at `wb` about its
/// centre, which is at
///   p(t) = b.center + w t - arc(t),
/// arc(t) the displacement of a's centre that turns with a: a centre fixed in a frame that turns
/// at wa about another point (a link of a robot under a twist, or of a frame along a turning
/// path segment) has a velocity that turns with it; `a_arc_velocity` is that velocity at t = 0
/// (arcDisplacement(), arc_motion.h). It is 0 for firstContact()'s pairs, whose centres move on
/// lines.
struct RotatingPair {
  Ellipse a;
  Ellipse b;
  Eigen::Vector2d w{0.0, 0.0};               ///< v_b - v_a, the part that does not turn [m/s]
  double wa{0.0}, wb{0.0};                   ///< angular velocities [rad/s]
  Eigen::Vector2d a_arc_velocity{0.0, 0.0};  ///< of a's centre at t = 0, turning at wa [m/s]
  /// What rounding to double left out of the fields above where they were computed from the
  /// motions (field + low part is exact to long double precision): near a tangency the pair is
  /// evaluated again in long double, where an ulp of a coordinate is no longer negligible.
  struct LowParts {
    Eigen::Vector2d b_center{0.0, 0.0};
    Eigen::Vector2d w{0.0, 0.0};
    Eigen::Vector2d a_arc_velocity{0.0, 0.0};
    double a_angle{0.0};
  } low;

  Ellipse aAt(double t) const {
    Ellipse e = a;
    e.angle = a.angle + wa * t;
    return e;
  }
  Ellipse bAt(double t) const {
    Ellipse e = b;
    e.center = b.center + w * t;
    if (hasArc()) e.center -= arcAt(t);
    e.angle = b.angle + wb * t;
    return e;
  }
  /// dp/dt at t: w - R(wa t) a_arc_velocity [m/s].
  Eigen::Vector2d centreVelocityAt(double t) const { return hasArc() ? w - arcVelocityAt(t) : w; }
  bool hasArc() const { return a_arc_velocity.x() != 0.0 || a_arc_velocity.y() != 0.0; }
  /// The arc's displacement of a's centre at t, and its velocity there [m, m/s].
  Eigen::Vector2d arcAt(double t) const;
  Eigen::Vector2d arcVelocityAt(double t) const;
};

// Inline: the steps take them at every t.
inline Eigen::Vector2d RotatingPair::arcAt(double t) const {
  const Displacement<double> arc = arcDisplacement(a_arc_velocity.x(), a_arc_velocity.y(), wa, t);
  return {arc.x, arc.y};
}

inline Eigen::Vector2d RotatingPair::arcVelocityAt(double t) const {
  const SinCos turn = sinCos(wa * t);
  return {turn.cos * a_arc_velocity.x() - turn.sin * a_arc_velocity.y(),
          turn.sin * a_arc_velocity.x() + turn.cos * a_arc_velocity.y()};
}

/// The pair of `a`, whose centre moves at `a_velocity` plus `a_arc_velocity` turning at `wa` and
/// which turns at `wa` itself, and `b` moving by `motion_b`, in a's frame (RotatingPair), with the
/// low parts of b's relative centre and velocity.
RotatingPair rotatingPair(const Ellipse& a, const Eigen::Vector2d& a_velocity,
                          const Eigen::Vector2d& a_arc_velocity, double wa, const Ellipse& b,
                          const Motion& motion_b);

/// segmentContact()'s pair for an offset link of a turning frame: its centre on the line plus an
/// arc about the frame's origin.
RotatingPair segmentPair(const Ellipse& link_in_moving, const SegmentMotion& motion,
                         const Ellipse& obstacle, const Motion& obstacle_motion);

/// The double nearest to `exact`, and in `low` what it leaves out.
inline double split(long double exact, double* low) {
  const double high = static_cast<double>(exact);
  *low = static_cast<double>(exact - high);
  return high;
}

}  // namespace ellipse_collision::core::detail
