#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <limits>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"

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

/// The pair of `a`, whose centre moves at `a_velocity` plus `a_arc_velocity` turning at `wa` and
/// which turns at `wa` itself, and `b` moving by `motion_b`, in a's frame (RotatingPair), with the
/// low parts of b's relative centre and velocity.
RotatingPair rotatingPair(const Ellipse& a, const Eigen::Vector2d& a_velocity,
                          const Eigen::Vector2d& a_arc_velocity, double wa, const Ellipse& b,
                          const Motion& motion_b);

/// segmentContact()'s pair for an offset link of a turning frame: its centre on the line plus an
/// arc about the frame's origin (defined in path_motion.cpp).
RotatingPair segmentPair(const Ellipse& link_in_moving, const SegmentMotion& motion,
                         const Ellipse& obstacle, const Motion& obstacle_motion);

/// Resolution of the first contact of a rotating pair, relative to the horizon: the answer is
/// never later than the true first contact and, where the pair overlaps within this of it, no more
/// than this earlier.
inline constexpr double kRotationResolution = 2.5e-10;
/// Safety cap on the steps; the tests and the benchmark count the pairs that reach it (none, up
/// to axis ratios of 1e8 for two needles turning at different rates and 1e14 for a needle
/// against a disc). A pair that reaches it is claimed in contact where the steps stopped, never
/// late.
inline constexpr int kMaxRotationSteps = 20000;
/// A pair within this distance, relative to r_a + r_b, at a time where the steps cannot go on is
/// at a tangency: reported in contact there (see rotating_contact.cpp).
inline constexpr double kGrazeDistance = 5e-10;
/// Steps are shrunk by this against the ~1e-16 relative rounding of the distance and of t + step.
inline constexpr double kStepShrink = 1.0 - 1e-9;

/// What one call did, for the tests and the benchmark.
struct RotationWork {
  int distance_calls{0};
  bool capped{false};
};

/// The first contact in [0, horizon] of a rotating pair apart at t = 0 (see rotating_contact.cpp):
/// never late, at most kRotationResolution * horizon early where the pair overlaps within that of
/// it, and in contact at a tangency within the kGrazeDistance band. `work`, when given, receives
/// the work done. With `until` < horizon the steps stop once the next one would pass `until`: the
/// answer is the horizon's answer when that is a contact at or before `until`, and no contact
/// otherwise (the same steps, so the same time: a caller that needs only contacts up to `until`
/// loses nothing).
FirstContact rotatingContact(const RotatingPair& pair, double horizon, RotationWork* work = nullptr,
                             double until = std::numeric_limits<double>::infinity());

/// Largest |w - R(s) v| [m/s] over the turns s between 0 and `turn` [rad]: a bound on the speed of
/// a centre whose velocity is w plus v turning (rotating_contact.cpp).
double largestCentreSpeed(const Eigen::Vector2d& w, const Eigen::Vector2d& v, double turn);

/// The double nearest to `exact`, and in `low` what it leaves out.
inline double split(long double exact, double* low) {
  const double high = static_cast<double>(exact);
  *low = static_cast<double>(exact - high);
  return high;
}

/// Time 0 means overlapping now (firstContact()'s rule): a contact found at 0 for a pair that
/// overlap() calls apart is reported at the first time after 0.
inline FirstContact apartAtZero(FirstContact contact, double horizon) {
  if (contact.contact && contact.time == 0.0) {
    contact.time = std::min(horizon, std::numeric_limits<double>::denorm_min());
  }
  return contact;
}

}  // namespace ellipse_collision::core::detail
