#include "ellipse_collision/core/distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ellipse_collision/core/overlap.h"

namespace ellipse_collision::core {
namespace {

using Eigen::Vector2d;

// Notation. d = c_b - c_a [m]; u = (cos theta, sin theta) a unit direction; u' = du/dtheta =
// perp(u). h(u) = max over the centred ellipse of u.x = |(rx u.ex, ry u.ey)| is its support
// function [m]. The dual objective f(u) = u.d - h_a(u) - h_b(u) [m] is the width of the gap between
// the two support lines of normal u; its maximum over u is the distance when the ellipses are
// separated.
//
// Why the bracketed search below is safe. Writing L = (rx u.ex, ry u.ey), L' = (-rx u.ey, ry u.ex)
// and L x L' = rx ry, one gets h'' = (rx ry)^2 / h^3 - h, hence
//   f'' = -f - (rx_a ry_a)^2 / h_a^3 - (rx_b ry_b)^2 / h_b^3 < 0   wherever f >= 0,
// so f is strictly concave in theta on the arc where it is positive. That arc is connected: the
// set {u : f(u/|u|) > 0} is the convex cone {g(v) > 0} of the concave, positively homogeneous
// g(v) = v.d - h_a(v) - h_b(v), and g(v) + g(-v) < 0 keeps it inside the open half-plane v.d > 0.
// Outside the arc f may have other (negative) local maxima, so there the search follows a second,
// globally concave function instead: on the line v = d^ + s perp(d^) (s = tan theta, theta from
// d^), G(s) = g(v) = |d| - h_a(v) - h_b(v) is concave in s and positive exactly on the same arc,
// which thus contains G's maximum. Inside the arc the sign of f', outside it the sign of G', tells
// on which side of the optimum an evaluation lies; that keeps a bracket [lo, hi] of angles around
// it. Halley (or Newton) steps are taken inside the bracket, bisections otherwise. On the flat side
// of a 1e3:1 ellipse f is sharply peaked (f'' ~ rx^2 / ry), and the bracket is what stops the
// steps from flying off the peak.

double cross(const Vector2d& v, const Vector2d& w) { return v.x() * w.y() - v.y() * w.x(); }

Vector2d perp(const Vector2d& v) { return {-v.y(), v.x()}; }

/// An ellipse's own axes; computed once per call so the loop needs no trigonometry.
struct Axes {
  Vector2d ex, ey;  // unit vectors of the ellipse's x and y axes
  double rx, ry;    // [m]
  double rx2, ry2;  // [m^2]
  double rxry2;     // (rx ry)^2 [m^4]
};

Axes axesOf(const Ellipse& e) {
  Axes axes;
  axes.ex = {std::cos(e.angle), std::sin(e.angle)};
  axes.ey = perp(axes.ex);
  axes.rx = e.radius_x;
  axes.ry = e.radius_y;
  axes.rx2 = e.radius_x * e.radius_x;
  axes.ry2 = e.radius_y * e.radius_y;
  axes.rxry2 = axes.rx2 * axes.ry2;
  return axes;
}

/// Support function of one centred ellipse at (almost) unit u and its theta derivatives.
struct Support {
  double p, q;         // u . ex, u . ey
  double h;            // h(u) [m]
  double inv_h;        // 1 / h [1/m]
  double dh;           // dh/dtheta [m]
  double curvature;    // (rx ry)^2 / h^3 = h'' + h, the rim's radius of curvature there [m]
  double slope_noise;  // bound on the rounding error of dh, in units of epsilon [m]
};

Support supportOf(const Axes& e, const Vector2d& u) {
  Support s;
  s.p = u.dot(e.ex);
  s.q = u.dot(e.ey);
  const double lx = e.rx * s.p;
  const double ly = e.ry * s.q;
  s.h = std::sqrt(lx * lx + ly * ly);
  s.inv_h = 1.0 / s.h;
  const double split = (e.ry2 - e.rx2) * s.inv_h;
  s.dh = split * s.p * s.q;
  s.curvature = e.rxry2 * s.inv_h * s.inv_h * s.inv_h;
  // p and q carry absolute errors of order epsilon; near a flat side dh amplifies them by rx / ry.
  s.slope_noise = std::abs(split) * (std::abs(s.p) + std::abs(s.q)) + s.h;
  return s;
}

/// Offset from the centre to the support point of the ellipse in the direction of `s` [m].
Vector2d supportPoint(const Axes& e, const Support& s) {
  return (e.rx2 * s.p * s.inv_h) * e.ex + (e.ry2 * s.q * s.inv_h) * e.ey;
}

// Error-free transformations (Knuth's TwoSum, FMA TwoProduct): a op b == hi + lo exactly. They
// need IEEE evaluation, so this file must not be built with -ffast-math.
struct Sum {
  double hi, lo;
};

Sum twoSum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

Sum twoProduct(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

/// v . w with about twice the working precision.
Sum dot2(const Vector2d& v, const Vector2d& w) {
  const Sum x = twoProduct(v.x(), w.x());
  const Sum y = twoProduct(v.y(), w.y());
  const Sum s = twoSum(x.hi, y.hi);
  return {s.hi, s.lo + x.lo + y.lo};
}

/// h(u) with about twice the working precision [m].
Sum preciseSupport(const Axes& e, const Vector2d& u) {
  const Sum p = dot2(u, e.ex);
  const Sum q = dot2(u, e.ey);
  const Sum lx = twoProduct(e.rx, p.hi);
  const Sum ly = twoProduct(e.ry, q.hi);
  const double lx_lo = lx.lo + e.rx * p.lo;
  const double ly_lo = ly.lo + e.ry * q.lo;
  const Sum xx = twoProduct(lx.hi, lx.hi);
  const Sum yy = twoProduct(ly.hi, ly.hi);
  const Sum sq = twoSum(xx.hi, yy.hi);
  const double sq_lo = sq.lo + xx.lo + yy.lo + 2.0 * (lx.hi * lx_lo + ly.hi * ly_lo);
  const double h = std::sqrt(sq.hi);
  // One Newton step on h^2 = sq: h^2 - sq.hi is exact by FMA.
  return {h, (sq_lo - std::fma(h, h, -sq.hi)) / (2.0 * h)};
}

/// f(u) = u . d - h_a(u) - h_b(u) with about twice the working precision, d = d_hi + d_lo [m]. At
/// the optimum f is a small difference of large terms: this keeps the distance's error at the
/// level of the inputs' own rounding (chiefly cos and sin of the angles).
double preciseGap(const Vector2d& u, const Vector2d& d_hi, const Vector2d& d_lo, const Axes& ea,
                  const Axes& eb) {
  const Sum ud = dot2(u, d_hi);
  const Sum ha = preciseSupport(ea, u);
  const Sum hb = preciseSupport(eb, u);
  const Sum s1 = twoSum(ud.hi, -ha.hi);
  const Sum s2 = twoSum(s1.hi, -hb.hi);
  return s2.hi + (s2.lo + s1.lo + ud.lo + u.dot(d_lo) - ha.lo - hb.lo);
}

// Convergence: f' is the tangential offset between the two support points [m] and, with f'' <= -f,
// bounds the distance still to gain by f'^2 / (2 f). Stop when |f'| is below a few rounding errors,
// or below both kSlopeTolerance of the pair's scale (|d| + radii) and kRelativeSlopeTolerance of
// f: the witness points are then within 1e-12 of the scale and the distance within 1e-14 relative.
constexpr double kSlopeNoiseFactor = 4.0;
constexpr double kSlopeTolerance = 1e-12;
constexpr double kRelativeSlopeTolerance = 1e-7;
// f in plain double is off by a few rounding errors of the scale |d| + radii; below this fraction
// of the scale that is more than 1e-12 relative, and the gap is recomputed in double-double.
constexpr double kPreciseGapBelow = 1e-4;
// Bisections alone reach the angular resolution of a double within ~60 steps.
constexpr int kMaxIterations = 100;

}  // namespace

Clearance distance(const Ellipse& a, const Ellipse& b) {
  Clearance result;
  if (overlap(a, b)) return result;
  result.separated = true;

  const Axes ea = axesOf(a);
  const Axes eb = axesOf(b);
  // Centres first, exactly as hi + lo: centres may be ~1e6 m out while the ellipses are small.
  const Vector2d d = b.center - a.center;
  const Vector2d d_lo(twoSum(b.center.x(), -a.center.x()).lo,
                      twoSum(b.center.y(), -a.center.y()).lo);
  const double d_norm = d.norm();  // > 0, since overlap() is false
  const Vector2d d_hat = d / d_norm;
  const Vector2d d_perp = perp(d_hat);
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  const double scale = d_norm + boundingRadius(a) + boundingRadius(b);  // [m]

  // The optimum lies strictly between lo and hi, ordered counter-clockwise; the first evaluation
  // at d^ halves this half-plane so that lo + hi never vanishes when bisecting.
  Vector2d lo = -d_perp;
  Vector2d hi = d_perp;
  Vector2d u = d_hat;
  // Best point so far: positive f with the smallest |f'| (f' is the tangential offset between the
  // two support points); while no f is positive, the largest f.
  bool found_positive = false;
  Vector2d best_u = u;
  Support best_a{}, best_b{};
  double best_f = -std::numeric_limits<double>::infinity();
  double best_slope = std::numeric_limits<double>::infinity();  // |f'| at best_u once positive
  // Squared chords |u_new - u_old|^2 of the last two updates: a step must at least halve the older
  // one, otherwise it is making slow progress and a bisection replaces it (as in rtsafe).
  double step2 = std::numeric_limits<double>::infinity();
  double step2_old = step2;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const Support sa = supportOf(ea, u);
    const Support sb = supportOf(eb, u);
    const Vector2d u_perp = perp(u);
    const double f = u.dot(d) - sa.h - sb.h;
    const double df = u_perp.dot(d) - sa.dh - sb.dh;
    const bool better = f > 0.0 ? std::abs(df) < best_slope : !found_positive && f > best_f;
    if (better) {
      best_f = f;
      best_u = u;
      best_a = sa;
      best_b = sb;
      if (f > 0.0) {
        found_positive = true;
        best_slope = std::abs(df);
      }
    }

    bool optimum_ccw;  // the optimum is counter-clockwise of u
    Vector2d candidate;
    if (f > 0.0) {
      const double noise = kEpsilon * (d_norm + sa.slope_noise + sb.slope_noise);
      const double tolerance =
          std::max(kSlopeNoiseFactor * noise,
                   std::min(kSlopeTolerance * scale, kRelativeSlopeTolerance * f));
      if (std::abs(df) <= tolerance) break;
      const double d2f = -f - sa.curvature - sb.curvature;  // < 0, see above
      // (rx ry)^2 / h^3 has the derivative -3 (rx ry)^2 h' / h^4.
      const double d3f =
          -df + 3.0 * (sa.curvature * sa.dh * sa.inv_h + sb.curvature * sb.dh * sb.inv_h);
      optimum_ccw = df > 0.0;
      // Halley step t = num / den = -2 f' f'' / (2 f''^2 - f' f'''), or Newton's -f' / f'' where
      // f''' would double it or reverse it. Taken as the rotation by 2 atan(t/2), which agrees with
      // t to third order and needs one division and no square root:
      //   cos = (4 den^2 - num^2) / (4 den^2 + num^2),  sin = 4 num den / (4 den^2 + num^2).
      double num = -2.0 * df * d2f;
      double den = 2.0 * d2f * d2f - df * d3f;
      if (!(den > d2f * d2f)) {
        num = -df;
        den = d2f;
      }
      const double n2 = num * num;
      const double d2 = 4.0 * den * den;
      const double inv = 1.0 / (d2 + n2);
      candidate = ((d2 - n2) * inv) * u + (4.0 * num * den * inv) * u_perp;
    } else {
      // Outside the positive arc: one Newton step on the concave G(s) towards its maximum.
      const double cos_theta = u.dot(d_hat);
      const double sin_theta = cross(d_hat, u);
      // G(s) = f / cos theta, so dG/ds = f' cos theta + f sin theta.
      const double dG = df * cos_theta + f * sin_theta;
      const double c3 = cos_theta * cos_theta * cos_theta;
      const double d2G = -(sa.curvature + sb.curvature) * c3;  // h(v) = h(u) / cos theta
      optimum_ccw = dG > 0.0;
      const double s_new = sin_theta / cos_theta - dG / d2G;
      candidate = (d_hat + s_new * d_perp).normalized();
    }
    if (optimum_ccw) {
      lo = u;
    } else {
      hi = u;
    }

    const double candidate_step2 = (candidate - u).squaredNorm();
    const bool inside = cross(lo, candidate) > 0.0 && cross(candidate, hi) > 0.0;
    const double step2_before_last = step2_old;
    step2_old = step2;
    if (inside && 4.0 * candidate_step2 <= step2_before_last) {
      step2 = candidate_step2;
      u = candidate;
    } else {
      const Vector2d mid = (lo + hi).normalized();
      if (!(cross(lo, mid) > 0.0 && cross(mid, hi) > 0.0)) break;  // bracket at resolution
      step2 = (mid - u).squaredNorm();
      u = mid;
    }
  }

  result.point_a = a.center + supportPoint(ea, best_a);
  result.point_b = b.center - supportPoint(eb, best_b);
  // |best_u| is 1 up to the rounding of the rotations, which scales f alike: negligible.
  if (best_f <= 0.0) {
    result.distance = 0.0;
  } else if (best_f < kPreciseGapBelow * scale) {
    result.distance = std::max(0.0, preciseGap(best_u, d, d_lo, ea, eb));
  } else {
    result.distance = best_f;
  }
  return result;
}

}  // namespace ellipse_collision::core
