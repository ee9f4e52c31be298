#include "rotating_step_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rotating_contact.h"

namespace ellipse_collision::core::detail {
namespace {

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

/// K = rho - h of an ellipse of radii big >= small (doc/rotating_contact.md), bounded over the
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
/// (doc/rotating_contact.md), P = `farthest`, with K of each ellipse from
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

}  // namespace

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

}  // namespace ellipse_collision::core::detail
