#include "rotating_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "arc_motion.h"
#include "sin_cos.h"

namespace ellipse_collision::core::detail {

// Conservative advancement (Mirtich 1996; Zhang, Lee, Kim, Manocha 2006) on the exact distance,
// with second-order steps.
// For a fixed unit u the support-function dual (distance.h) gives, at every t,
//   D(t) >= f(u, t) = u . p(t) - h_a(u, t) - h_b(u, t),
// and f(u, t) > 0 means u separates the pair (no overlap); D(t) is the largest f over u.
// First order: p'(t) = w - R(wa t) v_arc (v_arc: a_arc_velocity), whose length over the turn is
// at most V_p = max over s in [0, wa horizon] of |w - R(s) v_arc| (largestCentreSpeed()); an
// ellipse of semi-axes R >= r turning at omega has |dh/dt| = |omega| |dh/dphi| <= |omega| (R - r)
// (the largest distance from the centre to a normal line of the ellipse is R - r). A maximum of
// functions with a common Lipschitz constant has it too, so |D'| <= V = V_p + |wa| (R_a - r_a) +
// |wb| (R_b - r_b) and no contact happens in [t, t + D(t) / V).
// Second order, along the witness direction u of the distance at t (where f(u, t) = D(t)):
//   f'' = u . p'' - h_a'' - h_b''.
// p''(t) = -wa z x R(wa t) v_arc is the centripetal acceleration of a's centre on its arc, of
// length |wa| |v_arc| (= wa^2 times the arc's radius), so u . p'' >= -|wa| |v_arc|. An ellipse
// turning at omega has h'' = omega^2 (rho - h), rho = r_x^2 r_y^2 / h^3 its radius of curvature
// at normal u (h + h'' = rho for a support function of the normal angle, and turning the shape by
// theta turns its normal angle by -theta), and rho - h <= R^2 / r - r. So f'' >= -M with
//   M = |wa| |v_arc| + omega_a^2 (R_a^2 / r_a - r_a) + omega_b^2 (R_b^2 / r_b - r_b),
// and by Taylor's theorem f(u, t + s) >= f + f' s - M s^2 / 2 for s >= 0, with the exact rate
// f' = u . p'(t) - omega_a dh_a/dtheta_a - omega_b dh_b/dtheta_b at t (theta the ellipse's
// angle). No contact happens before the positive root of that quadratic. The step is the larger
// of that root and D / V; both are certified.
// A direction that turns: M above holds the worst curvature of a support function over all
// directions, R^2 / r at a needle's flat side, which the witness direction of a turning needle
// sees only because u stays fixed while the needle turns under it. Along u(s) = R(omega_u s) u
// (s from t) the separation f(u(s), s) is still a lower bound of D, h_e changes only with the
// angle between u and e, at omega_e - omega_u, and d2/ds2 (u . p) = -omega_u^2 u . p +
// 2 omega_u u_perp . p' + u . p'', so
//   f'' >= -M_u,  M_u = omega_u^2 P + 2 |omega_u| V_p + |wa| |v_arc|
//                     + (omega_u - wa)^2 (R_a^2 / r_a - r_a) + (omega_u - wb)^2 (R_b^2 / r_b - r_b),
// P a bound of |p| over the step: |p(t)| + V_p s, with s held to a cap (below). omega_u minimises
// M_u (a convex quadratic plus 2 V_p |omega_u|): for a turning needle against a disc it is about
// the needle's own rate, and M_u drops from omega^2 R^2 / r to about omega^2 |p| + 2 |omega| V_p,
// free of the axis ratio. f' there is u . p' + omega_u u_perp . p + (omega_u - wa) dh_a/dtheta_a +
// (omega_u - wb) dh_b/dtheta_b, less its rounding. The step is the largest of the three roots
// (first order, fixed u, turning u); each is certified. The witness direction of a needle is taken
// with care too (below). Fuzzer pairs, a disc by a needle 1.4e14 or 2e12 long to thin and turning
// slowly, reached the 20,000-step cap at first-order steps (the direction between the witness
// points was off along the needle, and M of the fixed direction 1.3e8 and 4.7e14 m/s^2); they now
// take 2 to 8 steps.
// Over the angles a step sweeps: no one direction turns with two needles that turn at different
// rates, and with K = R^2 / r - r over all directions M_u kept about (wa - wb)^2 times the smaller
// R^2 / r: their steps shrank with the axis ratio (about as its power -0.37, the cap from ratios of
// about 1e7). But K is the worst of rho - h over every direction, while a step of length s turns
// the direction against an ellipse by at most |omega_rel| s (omega_e for u fixed, omega_e - omega_u
// for u turning): rho - h is then bounded over that arc of directions alone (sweptCurvature()),
// R^2 / r only where the arc reaches the flat side's normal. A needle seen near its tips curves as
// little as r^2 / R there. The bound holds only for steps within the length s it was taken for (a
// cap), so the step is min(root, cap), the cap starting at twice the step the curvatures at t alone
// would give and growing by 8 while it, not the root, holds the step back; the fixed direction's
// bound over all directions stays as a floor (the turning direction's over all directions gave no
// longer steps once the swept one was taken, and cost 2-8 % of the time). Two needles of axis ratio
// 1e8 turning at rates 0.2..6 rad/s apart, touching tip to tip or tip to flat side, take 29 to 38
// distance() calls on average through a grazing pass, as at ratio 1e2 (before: 10,000 to 15,000, a
// half at the cap).
// Approaching a transversal contact the root is a Newton step from the left (quadratic convergence,
// never past the contact); through a grazing pass of gap g the steps stay about sqrt(2 g / M) (a
// few steps for the whole pass instead of sqrt(size / g)); into an exact tangency they shrink
// geometrically. f is evaluated in double with a rounding allowance of 16 eps of its terms (each h
// counted as its support point's distance from the centre, SupportRates, times 1 + |angle| of its
// pose, whose rounding turns it); a pass within ~1e-14 of the radii of touching leaves nothing of f
// above that allowance, and where the steps would then stop short of a contact f is evaluated again
// in long double (64-bit significand), where the allowance is 2048 times smaller: a contact grazed
// 1e-12 deep is crossed at ~1e-7 m/s, and the double allowance alone stopped the steps up to ~6e-8
// of the horizon before it. Below gaps of 1e-10 of the radii the witness points' rounding can turn,
// or reverse, the direction between them: a's rim normal at its point is taken; where the direction
// gives a separation below half the distance, the rim normals at both witness points are tried too
// (a needle's witness point can lie far along its flat side).
// Stopping: once a step is below the resolution (kRotationResolution * horizon), overlap() one
// resolution ahead; if the pair overlaps there, the first contact lies within the resolution
// after t and t is the answer (never late, at most one resolution early). If not and the distance
// is within the grazing band (kGrazeDistance of r_a + r_b), the pair is at a tangency within the
// band and reported in contact at t: the contact scale is then within kGrazeDistance of 1 (the
// Minkowski sum contains the disc of radius r_a + r_b). Otherwise the steps go on.
// Where M is below the normal range (an angular velocity whose square underflows) or overflows
// it is not trusted, and the steps are the plain D / V ones, stopped in the grazing band.
namespace {

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

// h and its derivatives along u. The rounding of the axis components ax, ay (~eps absolute)
// moves h by up to eps (r_x^2 |ax| + r_y^2 |ay|) / h, the distance of the support point from the
// centre along the axes (`reach`, >= h): for a needle seen near its flat side that is far more
// than eps h. It moves dh/dtheta by up to eps |r_x^2 - r_y^2| (|ax| + |ay|) / h (`dh_spread`).
struct SupportRates {
  double h, dh_dangle, curvature_radius;
  double reach, dh_spread;
  AxisShares shares;
};

SupportRates supportRates(const Ellipse& e, const SinCos& trig, const Eigen::Vector2d& u) {
  const double ax = u.x() * trig.cos + u.y() * trig.sin;  // u . x axis
  const double ay = u.y() * trig.cos - u.x() * trig.sin;  // u . y axis
  const double rx2 = e.radius_x * e.radius_x, ry2 = e.radius_y * e.radius_y;
  const double h = std::sqrt(rx2 * ax * ax + ry2 * ay * ay);
  const double fx = std::fabs(ax), fy = std::fabs(ay);
  // One division for the four quotients: each step evaluates this up to 16 times.
  const double inverse = 1.0 / h;
  // d(ax)/dangle = ay, d(ay)/dangle = -ax; turning u by phi is turning the shape by -phi.
  return {h,
          (rx2 - ry2) * ax * ay * inverse,
          rx2 * ry2 * (inverse * inverse * inverse),
          (rx2 * fx + ry2 * fy) * inverse,
          std::fabs(rx2 - ry2) * (fx + fy) * inverse,
          rx2 >= ry2 ? AxisShares{fx, fy} : AxisShares{fy, fx}};
}

SeparationAlong separationAlong(const SinCosPair& trig, const Ellipse& a, const Ellipse& b,
                                const Eigen::Vector2d& centre_velocity, double wa, double wb,
                                const Eigen::Vector2d& u) {
  const SupportRates sa = supportRates(a, trig.first, u);
  const SupportRates sb = supportRates(b, trig.second, u);
  const Eigen::Vector2d centres = b.center - a.center;
  const double along = u.dot(centres);
  const double across = u.x() * centres.y() - u.y() * centres.x();  // (u turned +90 deg) . p
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double value = along - sa.h - sb.h;
  // h'' = rho - h for a support function of the normal angle, so f'' = -f - rho_a - rho_b.
  const double centre_rate = u.dot(centre_velocity);
  // The poses' angles are rounded to eps of their size, which moves each support point by its
  // reach times that: a pose whose angle is far from 0 turns by whole ulps (one of 6.9e274 rad
  // did not turn at all, while the rates below had it turn; a step passed a contact).
  return {value,
          centre_rate - wa * sa.dh_dangle - wb * sb.dh_dangle,
          16.0 * kEps *
              (std::fabs(along) + sa.reach * (1.0 + std::fabs(a.angle)) +
               sb.reach * (1.0 + std::fabs(b.angle))),
          across + sa.dh_dangle + sb.dh_dangle,
          -value - sa.curvature_radius - sb.curvature_radius,
          centre_rate,
          across,
          sa.dh_dangle,
          sb.dh_dangle,
          sa.dh_spread,
          sb.dh_spread,
          sa.shares,
          sb.shares};
}

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

/// f(u, t) (the comment above) evaluated in long double from the pair's motion (poses, arc and
/// angles at t in long double too), for gaps below the double allowance: `value` is f less its
/// rounding, rounded down to a double, and `rounding` 0; the rate's parts are those of the same
/// direction. u need not be of unit length. The direction is refined by Newton steps on its angle
/// in long double too: the double one is the best only for the double poses, and a needle turned
/// by the ~1e-16 rad between them moves its support point far along its flat side (by 6e5 m for
/// one 5.8e7 m long and 5.8e-7 m thin, which cost the separation 3e-11 m of a 4e-17 m gap).
/// For the same reason the separation is evaluated in the frame of the ellipse with the larger
/// sweep curvature (`frame`): there u . its axes is exact, u's angle to its flat side is held
/// to a relative precision, and the rounding of its angle moves only the other centre (by |p|
/// times it) instead of its support point (by R^2 / r times it: for an axis ratio of 1e14 that
/// alone outgrew a gap of 1e-12 of the radii).
/// Out of line: the steps need it only near a tangency.
[[gnu::noinline]] SeparationAlong preciseSeparation(const RotatingPair& p, double t,
                                                    const Eigen::Vector2d& centre_velocity,
                                                    const Eigen::Vector2d& direction,
                                                    bool frame_of_a) {
  using Long = long double;
  const Long time = t;
  const auto exact = [](double high, double low) { return Long(high) + low; };
  Long px = exact(p.b.center.x(), p.low.b_center.x()) + exact(p.w.x(), p.low.w.x()) * time;
  Long py = exact(p.b.center.y(), p.low.b_center.y()) + exact(p.w.y(), p.low.w.y()) * time;
  if (p.hasArc()) {
    const Displacement<Long> arc =
        arcDisplacement<Long>(exact(p.a_arc_velocity.x(), p.low.a_arc_velocity.x()),
                              exact(p.a_arc_velocity.y(), p.low.a_arc_velocity.y()), p.wa, time);
    px -= arc.x;
    py -= arc.y;
  }
  // The frame's angle, and the other ellipse's angle in it.
  const Long angle_a = exact(p.a.angle, p.low.a_angle), angle_b = p.b.angle;
  const Long frame = frame_of_a ? angle_a + Long(p.wa) * time : angle_b + Long(p.wb) * time;
  const Long other = frame_of_a ? (angle_b - angle_a) + (Long(p.wb) - p.wa) * time
                                : (angle_a - angle_b) + (Long(p.wa) - p.wb) * time;
  const Long fc = std::cos(frame), fs = std::sin(frame);
  const auto toFrame = [&](Long x, Long y, Long* fx, Long* fy) {
    *fx = fc * x + fs * y;
    *fy = fc * y - fs * x;
  };
  const Long p_norm = std::hypot(px, py);
  toFrame(Long(px), Long(py), &px, &py);
  Long vx, vy;
  toFrame(centre_velocity.x(), centre_velocity.y(), &vx, &vy);
  struct Axes {
    Long c, s, rx2, ry2;
  };
  const auto axes = [](const Ellipse& e, Long c, Long s) {
    return Axes{c, s, Long(e.radius_x) * e.radius_x, Long(e.radius_y) * e.radius_y};
  };
  const Axes own = axes(frame_of_a ? p.a : p.b, 1, 0);
  const Axes turned = axes(frame_of_a ? p.b : p.a, std::cos(other), std::sin(other));
  const Axes& ea = frame_of_a ? own : turned;
  const Axes& eb = frame_of_a ? turned : own;
  struct Support {
    Long h, dh, rho, reach, spread;
    AxisShares shares;
  };
  // As supportRates(), in long double.
  const auto support = [](const Axes& e, Long ux, Long uy) {
    const Long ax = ux * e.c + uy * e.s, ay = uy * e.c - ux * e.s;
    const Long h = std::sqrt(e.rx2 * ax * ax + e.ry2 * ay * ay);
    const Long fx = std::fabs(ax), fy = std::fabs(ay);
    const double along_x = static_cast<double>(fx), along_y = static_cast<double>(fy);
    return Support{h,
                   (e.rx2 - e.ry2) * ax * ay / h,
                   e.rx2 * e.ry2 / (h * h * h),
                   (e.rx2 * fx + e.ry2 * fy) / h,
                   std::fabs(e.rx2 - e.ry2) * (fx + fy) / h,
                   e.rx2 >= e.ry2 ? AxisShares{along_x, along_y} : AxisShares{along_y, along_x}};
  };
  // The rounding of the frame's angle moves the other centre by |p| times it, and that of the
  // other's angle its support point by its reach times it.
  const Long frame_error = 1 + std::fabs(frame), other_error = 1 + std::fabs(other);
  const Long norm = std::hypot(Long(direction.x()), Long(direction.y()));
  Long ux, uy;
  toFrame(direction.x() / norm, direction.y() / norm, &ux, &uy);
  constexpr Long kEps = std::numeric_limits<Long>::epsilon();
  SeparationAlong best{};
  Long best_lower = -std::numeric_limits<Long>::infinity();
  for (int i = 0; i <= kDirectionSteps; ++i) {
    const Support sa = support(ea, ux, uy), sb = support(eb, ux, uy);
    const Long along = ux * px + uy * py, across = ux * py - uy * px;
    const Long value = along - sa.h - sb.h;
    const Support& so = frame_of_a ? sb : sa;
    const Long lower = value - 16 * kEps * (std::fabs(along) + p_norm * frame_error + sa.reach +
                                            sb.reach + so.reach * other_error);
    if (lower > best_lower) {
      best_lower = lower;
      const double centre_rate = static_cast<double>(ux * vx + uy * vy);
      // Shrunk by 2^-52 against the rounding to double.
      best = {static_cast<double>(lower) * (1.0 - 0x1p-52),
              static_cast<double>(centre_rate - p.wa * sa.dh - p.wb * sb.dh),
              0.0,
              static_cast<double>(across + sa.dh + sb.dh),
              static_cast<double>(-value - sa.rho - sb.rho),
              centre_rate,
              static_cast<double>(across),
              static_cast<double>(sa.dh),
              static_cast<double>(sb.dh),
              static_cast<double>(sa.spread),
              static_cast<double>(sb.spread),
              sa.shares,
              sb.shares};
    }
    // A Newton step on the angle of u where f is concave in it, as in bestSeparation().
    const Long curvature = -value - sa.rho - sb.rho;
    if (i == kDirectionSteps || !(curvature < 0)) break;
    const Long turn = -(across + sa.dh + sb.dh) / curvature;
    if (!(std::fabs(turn) < Long(0.5))) break;
    const Long c = std::cos(turn), s = std::sin(turn);
    const Long turned_x = c * ux - s * uy;
    uy = s * ux + c * uy;
    ux = turned_x;
  }
  return best;
}

// Below this gap, relative to R_a + R_b, the witness points' rounding (~eps R) can turn, or even
// reverse, the direction between them; the normal of a's rim at its witness point is then taken.
constexpr double kWitnessGap = 1e-10;

/// The unit outward normal of a's rim at its point `x`, or false when there is none. At a witness
/// point it is the direction from a to the other ellipse along which they are farthest apart (the
/// maximiser of the support-function dual, whose support point the witness point is).
bool rimNormal(const Ellipse& a, const Eigen::Vector2d& x, Eigen::Vector2d* normal) {
  const SinCos trig = sinCos(a.angle);
  const Eigen::Vector2d d = x - a.center;
  // In a's axes the rim is (x / r_x)^2 + (y / r_y)^2 = 1, whose gradient is the normal.
  const double nx = (trig.cos * d.x() + trig.sin * d.y()) / (a.radius_x * a.radius_x);
  const double ny = (trig.cos * d.y() - trig.sin * d.x()) / (a.radius_y * a.radius_y);
  const Eigen::Vector2d n(trig.cos * nx - trig.sin * ny, trig.sin * nx + trig.cos * ny);
  const double length = n.norm();
  if (!(length > 0.0)) return false;
  *normal = n / length;
  return true;
}

// The double separation is evaluated again in long double where its rounding allowance costs
// more than 1/64 of it (gaps below ~1e-13 of the radii) and the steps would stop.
constexpr double kPreciseBelow = 64.0;

/// The positive root of value + rate s - curvature s^2 / 2 (value > 0, curvature > 0; a curvature
/// of 0 gives the linear root, or infinity).
double quadraticStep(double value, double rate, double curvature) {
  // A curvature of 0 (a swept bound over a needle's tips, a pair with no turn) is the linear
  // bound, without dividing by it.
  if (!(curvature > 0.0)) {
    return rate < 0.0 ? value / -rate : std::numeric_limits<double>::infinity();
  }
  const double root = std::sqrt(rate * rate + 2.0 * curvature * value);
  // Each form where it has no cancellation.
  return rate > 0.0 ? (rate + root) / curvature : 2.0 * value / (root - rate);
}

double sweepCurvature(const Ellipse& e, double omega) {
  const double big = boundingRadius(e), small = inscribedRadius(e);
  return omega * omega * (big * (big / small) - small);
}

bool turns(const Ellipse& e, double omega) { return omega != 0.0 && e.radius_x != e.radius_y; }

}  // namespace

Eigen::Vector2d RotatingPair::arcAt(double t) const {
  const Displacement<double> arc = arcDisplacement(a_arc_velocity.x(), a_arc_velocity.y(), wa, t);
  return {arc.x, arc.y};
}

Eigen::Vector2d RotatingPair::arcVelocityAt(double t) const {
  const SinCos turn = sinCos(wa * t);
  return {turn.cos * a_arc_velocity.x() - turn.sin * a_arc_velocity.y(),
          turn.sin * a_arc_velocity.x() + turn.cos * a_arc_velocity.y()};
}

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

// |w - R(s) v|^2 = |w|^2 + |v|^2 - 2 |w| |v| cos(alpha + s), largest where alpha + s is nearest
// an odd multiple of pi.
double largestCentreSpeed(const Eigen::Vector2d& w, const Eigen::Vector2d& v, double turn) {
  const double a = std::hypot(w.x(), w.y()), c = std::hypot(v.x(), v.y());
  if (a == 0.0 || c == 0.0) return a + c;
  constexpr double kPi = 3.14159265358979323846;
  const double alpha = std::atan2(w.x() * v.y() - w.y() * v.x(), w.dot(v));
  const double lo = alpha + std::min(0.0, turn) - 1e-9, hi = alpha + std::max(0.0, turn) + 1e-9;
  if (std::ceil((lo - kPi) / (2.0 * kPi)) <= (hi - kPi) / (2.0 * kPi)) return a + c;
  const double c_end = std::cos(turn), s_end = std::sin(turn);
  const Eigen::Vector2d v_end(c_end * v.x() - s_end * v.y(), s_end * v.x() + c_end * v.y());
  return std::max((w - v).norm(), (w - v_end).norm()) * (1.0 + 1e-12);
}

namespace {

/// What the steps of one pair need besides the pair.
struct StepBounds {
  double approach_speed;  ///< V [m/s]
  double curvature;       ///< M [m/s^2]
  bool second_order;
  double graze;     ///< the grazing band [m]
  double tiny_gap;  ///< below it the witness direction is a's normal [m]
  // The turning direction's bound (turningRoot()):
  double centre_speed;    ///< V_p [m/s]
  double arc_curvature;   ///< |wa| |v_arc| [m/s^2]
  double sweep_a, sweep_b;  ///< K = R^2 / r - r of a and b, 0 for a circle [m]
  // The radii of a and b, R >= r, for K over the directions a step sweeps (sweptCurvature()).
  double big_a, small_a, big_b, small_b;
};

/// K = rho - h of an ellipse of radii big >= small (the comment at the top), bounded over the
/// directions within `spread` [rad] of a unit u whose shares are `u`, instead of over all
/// directions (`worst`, R^2 / r - r): rho - h = R^2 r^2 / h^3 - h falls as h grows, and h^2 =
/// r^2 + (R^2 - r^2) sin^2(beta), beta the angle of the direction to the short axis, whose least
/// over the spread is max(0, beta0 - spread) with sin(beta0 - spread) >= along_long (1 -
/// spread^2 / 2) - along_short spread. A needle seen near its tips curves as r^2 / R there, and a
/// step that sweeps only a small angle keeps its bound small, though a fixed direction or one
/// turning with the other ellipse sweeps it. Rounding: the shares and the bound are widened by
/// a few eps.
double sweptCurvature(double big, double small, double worst, const AxisShares& u, double spread) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  if (!(spread < 1.0) || small == big) return worst;
  const double sine =
      u.along_long * (1.0 - 0.5 * spread * spread) - u.along_short * spread - 4.0 * kEps;
  if (!(sine > 0.0)) return worst;
  const double h2 = small * small + (big * big - small * small) * (sine * sine);
  const double h = std::sqrt(h2);
  const double bound = (big * small) * (big * small) / (h2 * h) * (1.0 + 64.0 * kEps) -
                       h * (1.0 - 64.0 * kEps);
  return std::min(worst, std::max(0.0, bound));
}

/// The root of the second-order bound along u turning at the omega_u that minimises
/// M_u = omega_u^2 P + 2 |omega_u| V_p + |wa| |v_arc| + (omega_u - wa)^2 K_a + (omega_u - wb)^2 K_b
/// (the comment at the top), P = `farthest`, with K of each ellipse from
/// `sweep_a(omega_u - wa)` and `sweep_b(omega_u - wb)`; omega_u is chosen with `weight_a` and
/// `weight_b` in place of the K's. 0 where turning gives nothing. `value` is the separation along
/// u less its rounding; the rate's own rounding is taken off.
template <class SweepA, class SweepB>
double turningRoot(const StepBounds& k, const SeparationAlong& s, double value, double wa,
                   double wb, double centre_distance, double farthest, double weight_a,
                   double weight_b, SweepA sweep_a, SweepB sweep_b) {
  // M_u = A omega^2 - 2 B omega + 2 V_p |omega| + const, least at omega = (B -+ V_p) / A where
  // |B| > V_p (else at 0, the fixed direction). omega - wa and omega - wb are formed without
  // cancellation, and omega from the smaller of them, exactly the other being derived: an
  // ulp of omega - wa times a needle's dh/dtheta near its flat side (~eps R^2 / r per ulp of
  // the direction) would cost the rate more than the gap (one 1e14 long to thin stopped its
  // steps at 2.4e-10 s 6e-19 m from a contact 6e-9 s ahead).
  const double weighted = wa * weight_a + wb * weight_b;
  if (!(std::fabs(weighted) > k.centre_speed)) return 0.0;
  const double shift = std::copysign(k.centre_speed, weighted);
  const double sum = farthest + weight_a + weight_b;
  double da = ((wb - wa) * weight_b - wa * farthest - shift) / sum;
  double db = ((wa - wb) * weight_a - wb * farthest - shift) / sum;
  const bool from_a = std::fabs(da) <= std::fabs(db);
  const double omega = from_a ? wa + da : wb + db;
  (from_a ? db : da) = omega - (from_a ? wb : wa);
  if (!(omega != 0.0 && std::isfinite(omega) && std::isfinite(da) && std::isfinite(db))) {
    return 0.0;
  }
  const double curvature = omega * omega * farthest + 2.0 * std::fabs(omega) * k.centre_speed +
                           k.arc_curvature + da * da * sweep_a(da) + db * db * sweep_b(db);
  if (!(curvature >= std::numeric_limits<double>::min() &&
        curvature <= std::numeric_limits<double>::max())) {
    return 0.0;
  }
  // d/dt [u(t) . p(t) - h_a - h_b]: each h changes with the angle between u and its ellipse.
  const double terms[] = {s.centre_rate, omega * s.across, da * s.dh_a, db * s.dh_b};
  // The derived difference carries the rounding of omega too; u . p' and u_perp . p are
  // rounded to eps of |p'| <= V_p and |p|.
  double rate = 0.0,
         size = std::fabs(da) * s.dh_a_spread + std::fabs(db) * s.dh_b_spread +
                std::fabs(omega) * (std::fabs(from_a ? s.dh_b : s.dh_a) + centre_distance) +
                k.centre_speed;
  for (const double term : terms) rate += term, size += std::fabs(term);
  rate -= 16.0 * std::numeric_limits<double>::epsilon() * size;
  return quadraticStep(value, rate, curvature);
}

/// Where the separation was taken: what the second-order steps need of the poses at t.
struct StepContext {
  double centre_distance;      ///< |p(t)|, raised by its rounding [m]
  double margin_a, margin_b;   ///< the rounding of a's and b's angles at t [rad]
  double remaining;            ///< horizon - t [s]
};

/// The larger second-order step within `cap` [s] (fixed and turning u), the K's bounded over the
/// angles the step sweeps (sweptCurvature()) and P by |p(t)| + V_p cap: min(root, cap), or 0.
/// With `instant` the K's and P are those at t alone: not a bound, only the guess of the cap.
double sweptStep(const StepBounds& k, const SeparationAlong& s, double value, double wa,
                 double wb, const StepContext& at, double cap, bool instant) {
  const double reach = instant ? 0.0 : cap * (1.0 + 1e-12);
  // A rate against an ellipse (omega_u - omega_e) is off by the rounding of omega_u, which lies
  // between 0, wa and wb (the minimiser of a sum of convex terms centred there).
  const double rate_rounding = 4.0 * std::numeric_limits<double>::epsilon() *
                               (std::fabs(wa) + std::fabs(wb));
  const auto sweep_a = [&](double rate) {
    return sweptCurvature(k.big_a, k.small_a, k.sweep_a, s.shares_a,
                          (std::fabs(rate) + rate_rounding) * reach + at.margin_a);
  };
  const auto sweep_b = [&](double rate) {
    return sweptCurvature(k.big_b, k.small_b, k.sweep_b, s.shares_b,
                          (std::fabs(rate) + rate_rounding) * reach + at.margin_b);
  };
  const double weight_a = sweep_a(wa), weight_b = sweep_b(wb);
  const double fixed = k.arc_curvature + wa * wa * weight_a + wb * wb * weight_b;
  double root = quadraticStep(value, s.rate, fixed);
  const double farthest = (at.centre_distance + k.centre_speed * reach) * (1.0 + 1e-9);
  root = std::max(root, turningRoot(k, s, value, wa, wb, at.centre_distance, farthest, weight_a,
                                    weight_b, sweep_a, sweep_b));
  return instant ? root : std::min(root, cap);
}

/// The second-order step of a separation: the larger of the fixed direction's bound over all
/// directions and of the bounds over the angles a step sweeps (fixed and turning u), whose cap
/// starts at twice the step that the bounds at t alone would give and grows by 8 while it, not
/// the root, holds the step back.
double secondOrderStep(const StepBounds& k, const SeparationAlong& s, double value, double wa,
                       double wb, const StepContext& at) {
  double step = quadraticStep(value, s.rate, k.curvature);
  double cap = std::min(at.remaining, 2.0 * std::max(step, sweptStep(k, s, value, wa, wb, at,
                                                                     at.remaining, true)));
  for (int i = 0; i < 4 && cap > step; ++i) {
    const double swept = sweptStep(k, s, value, wa, wb, at, cap, false);
    step = std::max(step, swept);
    if (swept < cap || cap >= at.remaining) break;
    cap = std::min(at.remaining, 8.0 * cap);
  }
  return kStepShrink * step;
}

/// The steps of rotatingContact(); kArc: the pair has an arc (RotatingPair::hasArc()), so that
/// firstContact()'s pairs run without its branches.
template <bool kArc>
FirstContact advance(const RotatingPair& p, const StepBounds& k, double horizon, double until,
                     RotationWork& done) {
  const auto bAt = [&p](double t) {
    Ellipse e = p.b;
    e.center = p.b.center + p.w * t;
    if constexpr (kArc) e.center -= p.arcAt(t);
    e.angle = p.b.angle + p.wb * t;
    return e;
  };
  const auto centreVelocity = [&p](double t) {
    Eigen::Vector2d v = p.w;
    if constexpr (kArc) v -= p.arcVelocityAt(t);
    return v;
  };
  // |p(t)| from b's double pose at t, raised by what rounding the pose left out.
  const auto centreDistance = [&p](const Ellipse& b, double t) {
    double moved = p.b.center.norm() + p.w.norm() * t;
    if constexpr (kArc) moved += p.a_arc_velocity.norm() * t;
    return b.center.norm() + 4.0 * std::numeric_limits<double>::epsilon() * moved;
  };
  // What the second-order steps need of the poses at t.
  const auto contextAt = [&](const Ellipse& a, const Ellipse& b, double t) {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    return StepContext{centreDistance(b, t), 8.0 * kEps * (1.0 + std::fabs(a.angle)),
                       8.0 * kEps * (1.0 + std::fabs(b.angle)), horizon - t};
  };
  const double resolution = kRotationResolution * horizon;
  double t = 0.0;
  for (int i = 0; i < kMaxRotationSteps; ++i) {
    const Ellipse a = p.aAt(t), b = bAt(t);
    const Clearance c = distance(a, b);
    ++done.distance_calls;
    if (!c.separated) return {true, t};
    // Plain steps cannot resolve a grazing band; they stop there.
    if (!k.second_order && c.distance <= k.graze) return {true, t};
    double step = c.distance * kStepShrink / k.approach_speed;
    // A first-order step past `until` or the horizon decides as any longer one would: the gate's
    // search stops most pairs so, and the second order is not needed there.
    const bool decided = step >= resolution && t + step > std::min(until, horizon);
    // The direction between the witness points, or for a tiny gap a's normal at its own.
    Eigen::Vector2d direction = c.point_b - c.point_a;
    const double gap = direction.norm();
    bool blurred = false;  // the separation's rounding allowance costs much of it
    Eigen::Vector2d last_direction;
    if (k.second_order && !decided &&
        (gap > k.tiny_gap ? (direction /= gap, true) : rimNormal(a, c.point_a, &direction))) {
      const Eigen::Vector2d centre_velocity = centreVelocity(t);
      Separation s = bestSeparation(a, b, centre_velocity, p.wa, p.wb, direction);
      // A needle's witness point can lie anywhere along its flat side within rounding of the
      // distance, and the direction between the points then says nothing (one 1.4e14 long was
      // 3e5 m off along it, the separation along it -2.6e7 m for a gap of 3e-8 m): the rim
      // normals at the witness points, one of which is well placed, are tried too.
      if (!(s.best.value - s.best.rounding > 0.5 * c.distance)) {
        Eigen::Vector2d normal;
        for (int side = 0; side < 2; ++side) {
          if (!(side == 0 ? rimNormal(a, c.point_a, &normal)
                          : (rimNormal(b, c.point_b, &normal) && (normal = -normal, true)))) {
            continue;
          }
          const Separation other = bestSeparation(a, b, centre_velocity, p.wa, p.wb, normal);
          if (other.best.value - other.best.rounding > s.best.value - s.best.rounding) s = other;
        }
      }
      const double value = s.best.value - s.best.rounding;
      blurred = !(value > kPreciseBelow * s.best.rounding);
      last_direction = s.last_direction;
      if (value > 0.0) {
        step = std::max(step, secondOrderStep(k, s.best, value, p.wa, p.wb, contextAt(a, b, t)));
      }
    }
    if (step < resolution) {
      const double probe = std::min(t + resolution, horizon);
      if (overlap(p.aAt(probe), bAt(probe))) return {true, t};
      // The long double separation, where the double one's rounding holds the steps back.
      if (blurred) {
        const SeparationAlong precise =
            preciseSeparation(p, t, centreVelocity(t), last_direction, k.sweep_a >= k.sweep_b);
        if (precise.value > 0.0) {
          step = std::max(step, secondOrderStep(k, precise, precise.value, p.wa, p.wb,
                                                contextAt(a, b, t)));
        }
      }
      if (step < resolution && c.distance <= k.graze) return {true, t};  // a tangency in the band
    }
    const double next = t + step;
    if (next > until && until < horizon) return {};  // any contact comes after `until`
    if (next > horizon) {
      // [t, horizon] is certified clear unless the horizon itself touches: the last interval is
      // shortened to end exactly at the horizon and checked there.
      if (t == horizon) return {};
      t = horizon;
      continue;
    }
    if (!(next > t)) return {true, t};  // step below the resolution of t: certified safe here
    t = next;
  }
  done.capped = true;
  return {true, t};  // safety cap: no contact before t is certified, claim contact at t
}

}  // namespace

FirstContact rotatingContact(const RotatingPair& p, double horizon, RotationWork* work,
                             double until) {
  RotationWork local;
  RotationWork& done = work ? *work : local;
  done = {};
  StepBounds k;
  // Rounding of R - r is harmless: it is exact (Sterbenz) when r >= R / 2, and tiny against R.
  k.centre_speed = p.hasArc() ? largestCentreSpeed(p.w, p.a_arc_velocity, p.wa * horizon)
                              : std::hypot(p.w.x(), p.w.y());
  k.approach_speed = k.centre_speed +
                     std::fabs(p.wa) * (boundingRadius(p.a) - inscribedRadius(p.a)) +
                     std::fabs(p.wb) * (boundingRadius(p.b) - inscribedRadius(p.b));
  if (!(k.approach_speed > 0.0)) return {};
  k.arc_curvature = p.hasArc() ? std::fabs(p.wa) * p.a_arc_velocity.norm() : 0.0;
  k.curvature = sweepCurvature(p.a, p.wa) + sweepCurvature(p.b, p.wb) + k.arc_curvature;
  // A curvature bound below the normal range (an angular velocity whose square underflows) or
  // overflowed is not trusted: then the steps are the plain ones. A pair with no turn at all
  // (spinning circles, no arc) has f linear in t: its curvature 0 is exact.
  const bool linear = !turns(p.a, p.wa) && !turns(p.b, p.wb) && !p.hasArc();
  k.second_order = linear || (k.curvature >= std::numeric_limits<double>::min() &&
                              k.curvature <= std::numeric_limits<double>::max());
  k.graze = kGrazeDistance * (inscribedRadius(p.a) + inscribedRadius(p.b));
  k.tiny_gap = kWitnessGap * (boundingRadius(p.a) + boundingRadius(p.b));
  k.sweep_a = sweepCurvature(p.a, 1.0);
  k.sweep_b = sweepCurvature(p.b, 1.0);
  k.big_a = boundingRadius(p.a), k.small_a = inscribedRadius(p.a);
  k.big_b = boundingRadius(p.b), k.small_b = inscribedRadius(p.b);
  return p.hasArc() ? advance<true>(p, k, horizon, until, done)
                    : advance<false>(p, k, horizon, until, done);
}

}  // namespace ellipse_collision::core::detail
