#pragma once

// The separation f(u, t) = u . p(t) - h_a(u, t) - h_b(u, t) of a rotating pair along a direction
// u, a lower bound of their distance, with its rates and a bound on its rounding: in double for
// every step, and in long double near a tangency, where the double one's rounding would stop the
// steps (doc/rotating_contact.md). Internal to the core (src/core).

#include <Eigen/Core>
#include <cmath>

#include "ellipse_collision/core/ellipse.h"
#include "rotating_pair.h"
#include "sin_cos.h"

namespace ellipse_collision::core::detail {

// Where a unit u lies between an ellipse's tips and flat sides: |cos| and |sin| of its angle to
// the long axis (sweptCurvature()).
struct AxisShares {
  double along_long, along_short;
};

// The separation along a fixed unit u at the current poses, its rates in time and in the angle of
// u, with a bound on its rounding error.
struct SeparationAlong {
  double value, rate, rounding;
  double slope, curvature;  // d/dphi, d2/dphi2 of the value, phi the angle of u
  // The parts of the rate: u . p', (u turned +90 deg) . p, and dh/dtheta of a and b (theta the
  // ellipse's angle), for the rate in a turning direction (turningRoot()), with what bounds the
  // rounding of each dh/dtheta in units of eps (SupportRates).
  double centre_rate, across, dh_a, dh_b;
  double dh_a_spread, dh_b_spread;
  AxisShares shares_a, shares_b;  // of u against a and b
};

/// The separation of `a` and `b` along the unit `u` at their poses (`trig` their angles), its
/// rates with b's centre moving at `centre_velocity` and the ellipses turning at `wa` and `wb`.
SeparationAlong separationAlong(const SinCosPair& trig, const Ellipse& a, const Ellipse& b,
                                const Eigen::Vector2d& centre_velocity, double wa, double wb,
                                const Eigen::Vector2d& u);

// The distance's witness direction is accurate to ~1e-9 relative only down to gaps of ~1e-6 of
// the radii (distance.h); closer, its error costs the lower bound more than the gap itself. A
// few Newton steps on the angle of u (f is concave there) restore it; any u gives a valid bound,
// and the best one tried is kept, with the last one tried (the most accurate direction when
// rounding blurs which is best).
constexpr int kDirectionSteps = 3;

struct Separation {
  SeparationAlong best;
  Eigen::Vector2d last_direction;  // the last one tried
};

// Inlined into the steps, as before they had two forms (advance()): the call cost 1 % of the
// benchmark's rotating mix.
[[gnu::always_inline]] inline Separation bestSeparation(const Ellipse& a, const Ellipse& b,
                                                        const Eigen::Vector2d& centre_velocity,
                                                        double wa, double wb, Eigen::Vector2d u) {
  const SinCosPair trig = sinCosPair(a.angle, b.angle);
  SeparationAlong best = separationAlong(trig, a, b, centre_velocity, wa, wb, u);
  SeparationAlong current = best;
  for (int i = 0; i < kDirectionSteps && current.curvature < 0.0; ++i) {
    const double turn = -current.slope / current.curvature;
    if (!(std::fabs(turn) < 0.5)) break;
    const double c = std::cos(turn), s = std::sin(turn);
    u = Eigen::Vector2d(c * u.x() - s * u.y(), s * u.x() + c * u.y());
    current = separationAlong(trig, a, b, centre_velocity, wa, wb, u);
    if (current.value - current.rounding > best.value - best.rounding) best = current;
  }
  return {best, u};
}

// Below this gap, relative to R_a + R_b, the witness points' rounding (~eps R) can turn, or even
// reverse, the direction between them; the normal of a's rim at its witness point is then taken.
constexpr double kWitnessGap = 1e-10;

/// The unit outward normal of a's rim at its point `x`, or false when there is none. At a witness
/// point it is the direction from a to the other ellipse along which they are farthest apart (the
/// maximiser of the support-function dual, whose support point the witness point is).
bool rimNormal(const Ellipse& a, const Eigen::Vector2d& x, Eigen::Vector2d* normal);

// The double separation is evaluated again in long double where its rounding allowance costs
// more than 1/64 of it (gaps below ~1e-13 of the radii) and the steps would stop.
constexpr double kPreciseBelow = 64.0;

/// f(u, t) evaluated in long double from the pair's motion (poses, arc and angles at t in long
/// double too), for gaps below the double allowance: `value` is f less its rounding, rounded down
/// to a double, and `rounding` 0; the rate's parts are those of the same direction. u need not be of unit length. The direction is refined by Newton steps on its angle
/// in long double too: the double one is the best only for the double poses, and a needle turned
/// by the ~1e-16 rad between them moves its support point far along its flat side (by 6e5 m for
/// one 5.8e7 m long and 5.8e-7 m thin, which cost the separation 3e-11 m of a 4e-17 m gap).
/// For the same reason the separation is evaluated in the frame of the ellipse with the larger
/// sweep curvature (`frame`): there u . its axes is exact, u's angle to its flat side is held
/// to a relative precision, and the rounding of its angle moves only the other centre (by |p|
/// times it) instead of its support point (by R^2 / r times it: for an axis ratio of 1e14 that
/// alone outgrew a gap of 1e-12 of the radii).
/// Out of line: the steps need it only near a tangency.
SeparationAlong preciseSeparation(const RotatingPair& p, double t,
                                  const Eigen::Vector2d& centre_velocity,
                                  const Eigen::Vector2d& direction, bool frame_of_a);

}  // namespace ellipse_collision::core::detail
