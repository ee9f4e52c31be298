#include "rotating_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "conservative_advancement.h"
#include "sin_cos.h"

namespace ellipse_collision::core::detail {

// Conservative advancement with second-order steps. Plain conservative advancement
// (conservative_advancement.h) steps by D / V, the distance over a bound on its rate: near a
// grazing pass the steps shrink with the gap, about sqrt(size / gap) of them, and a pass within
// ~1e-8 of touching reaches any reasonable cap. Here each step also uses the shape of the
// separation along the current witness direction.
// For a fixed unit u the support-function dual (distance.h) gives, at every t,
//   D(t) >= f(u, t) = u . p(t) - h_a(u, t) - h_b(u, t),
// and f(u, t) > 0 means u separates the pair (no overlap). p(t) = p0 + w t is linear; an ellipse
// of semi-axes R >= r turning at omega has d2h/dt2 = omega^2 (rho - h), rho = r_x^2 r_y^2 / h^3
// its radius of curvature at normal u (h + h'' = rho for a support function, and turning the
// shape by theta turns its normal angle by -theta), so d2f/dt2 >= -M with
//   M = omega_a^2 (R_a^2 / r_a - r_a) + omega_b^2 (R_b^2 / r_b - r_b).
// By Taylor's theorem f(u, t + s) >= f + f' s - M s^2 / 2 for s >= 0, so no contact happens
// before the positive root of that quadratic, taken at the witness direction u of the distance at
// t (where f(u, t) = D(t)). The step is the larger of that root and D / V; both are certified.
// Approaching a transversal contact the root is a Newton step from the left (quadratic
// convergence, never past the contact); through a grazing pass of gap g the steps stay about
// sqrt(2 g / M) (a few steps for the whole pass instead of sqrt(size / g)); into an exact
// tangency they shrink geometrically.
// Stopping: once a step is below the resolution (kRotationResolution * horizon), overlap() one
// resolution ahead; if the pair overlaps there, the first contact lies within the resolution
// after t and t is the answer (never late, at most one resolution early). If not and the distance
// is within the grazing band of conservative_advancement.h, the pair is at a tangency within the
// band and reported in contact at t. Otherwise the steps go on.
namespace {

// The separation along a fixed unit u at the current poses, its rates in time and in the angle of
// u, with a bound on its rounding error.
struct SeparationAlong {
  double value, rate, rounding;
  double slope, curvature;  // d/dphi, d2/dphi2 of the value, phi the angle of u
};

struct SupportRates {
  double h, dh_dangle, curvature_radius;
};

SupportRates supportRates(const Ellipse& e, const SinCos& trig, const Eigen::Vector2d& u) {
  const double ax = u.x() * trig.cos + u.y() * trig.sin;  // u . x axis
  const double ay = u.y() * trig.cos - u.x() * trig.sin;  // u . y axis
  const double rx2 = e.radius_x * e.radius_x, ry2 = e.radius_y * e.radius_y;
  const double h = std::sqrt(rx2 * ax * ax + ry2 * ay * ay);
  // d(ax)/dangle = ay, d(ay)/dangle = -ax; turning u by phi is turning the shape by -phi.
  return {h, (rx2 - ry2) * ax * ay / h, rx2 * ry2 / (h * h * h)};
}

SeparationAlong separationAlong(const SinCosPair& trig, const Ellipse& a, const Ellipse& b,
                                const RotatingPair& p, const Eigen::Vector2d& u) {
  const SupportRates sa = supportRates(a, trig.first, u);
  const SupportRates sb = supportRates(b, trig.second, u);
  const Eigen::Vector2d centres = b.center - a.center;
  const double along = u.dot(centres);
  const double across = u.x() * centres.y() - u.y() * centres.x();  // (u turned +90 deg) . p
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double value = along - sa.h - sb.h;
  // h'' = rho - h for a support function of the normal angle, so f'' = -f - rho_a - rho_b.
  return {value, u.dot(p.w) - p.wa * sa.dh_dangle - p.wb * sb.dh_dangle,
          16.0 * kEps * (std::fabs(along) + sa.h + sb.h), across + sa.dh_dangle + sb.dh_dangle,
          -value - sa.curvature_radius - sb.curvature_radius};
}

// The distance's witness direction is accurate to ~1e-9 relative only down to gaps of ~1e-6 of
// the radii (distance.h); closer, its error costs the lower bound more than the gap itself. A
// few Newton steps on the angle of u (f is concave there) restore it; any u gives a valid bound,
// and the best one tried is kept.
constexpr int kDirectionSteps = 3;

SeparationAlong bestSeparation(const Ellipse& a, const Ellipse& b, const RotatingPair& p,
                               Eigen::Vector2d u) {
  const SinCosPair trig = sinCosPair(a.angle, b.angle);
  SeparationAlong best = separationAlong(trig, a, b, p, u);
  SeparationAlong current = best;
  for (int i = 0; i < kDirectionSteps && current.curvature < 0.0; ++i) {
    const double turn = -current.slope / current.curvature;
    if (!(std::fabs(turn) < 0.5)) break;
    const double c = std::cos(turn), s = std::sin(turn);
    u = Eigen::Vector2d(c * u.x() - s * u.y(), s * u.x() + c * u.y());
    current = separationAlong(trig, a, b, p, u);
    if (current.value - current.rounding > best.value - best.rounding) best = current;
  }
  return best;
}

/// The positive root of value + rate s - curvature s^2 / 2 (value > 0, curvature > 0).
double quadraticStep(double value, double rate, double curvature) {
  const double root = std::sqrt(rate * rate + 2.0 * curvature * value);
  // Each form where it has no cancellation.
  return rate > 0.0 ? (rate + root) / curvature : 2.0 * value / (root - rate);
}

double sweepCurvature(const Ellipse& e, double omega) {
  const double big = boundingRadius(e), small = inscribedRadius(e);
  return omega * omega * (big * (big / small) - small);
}

}  // namespace

Ellipse RotatingPair::aAt(double t) const {
  Ellipse e = a;
  e.angle = a.angle + wa * t;
  return e;
}

Ellipse RotatingPair::bAt(double t) const {
  Ellipse e = b;
  e.center = b.center + w * t;
  e.angle = b.angle + wb * t;
  return e;
}

FirstContact rotatingContact(const RotatingPair& p, double horizon, RotationWork* work) {
  RotationWork local;
  RotationWork& done = work ? *work : local;
  done = {};
  // Rounding of R - r is harmless: it is exact (Sterbenz) when r >= R / 2, and tiny against R.
  const double approach_speed =
      std::hypot(p.w.x(), p.w.y()) +
      std::fabs(p.wa) * (boundingRadius(p.a) - inscribedRadius(p.a)) +
      std::fabs(p.wb) * (boundingRadius(p.b) - inscribedRadius(p.b));
  if (!(approach_speed > 0.0)) return {};
  const double curvature = sweepCurvature(p.a, p.wa) + sweepCurvature(p.b, p.wb);
  // A curvature bound below the normal range (an angular velocity whose square underflows) or
  // overflowed is not trusted: then the steps are the plain ones.
  const bool second_order = curvature >= std::numeric_limits<double>::min() &&
                            curvature <= std::numeric_limits<double>::max();
  const double graze = kGrazeDistance * (inscribedRadius(p.a) + inscribedRadius(p.b));
  const double resolution = kRotationResolution * horizon;
  double t = 0.0;
  for (int i = 0; i < kMaxRotationSteps; ++i) {
    const Ellipse a = p.aAt(t), b = p.bAt(t);
    const Clearance c = distance(a, b);
    ++done.distance_calls;
    if (!c.separated) return {true, t};
    // Plain steps cannot resolve a grazing band; they stop there, as conservative_advancement.h.
    if (!second_order && c.distance <= graze) return {true, t};
    double step = c.distance * kStepShrink / approach_speed;
    const Eigen::Vector2d gap = c.point_b - c.point_a;
    const double gap_length = gap.norm();
    if (second_order && gap_length > 0.0) {
      const SeparationAlong s = bestSeparation(a, b, p, gap / gap_length);
      const double value = s.value - s.rounding;
      if (value > 0.0) step = std::max(step, kStepShrink * quadraticStep(value, s.rate, curvature));
    }
    if (step < resolution) {
      const double probe = std::min(t + resolution, horizon);
      if (overlap(p.aAt(probe), p.bAt(probe))) return {true, t};
      if (c.distance <= graze) return {true, t};  // a tangency within the grazing band
    }
    const double next = t + step;
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

}  // namespace ellipse_collision::core::detail
