#include "ellipse_collision/core/first_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/overlap.h"
#include "rotating_contact.h"
#include "sin_cos.h"

namespace ellipse_collision::core {
namespace {

// ---- translation: where the relative path enters the Minkowski sum --------------------------
// With both shapes fixed, b - a moves on the line p(t) = p0 + w t and the pair overlaps at t iff
// p(t) lies in the centred Minkowski sum K = A + B. K's support function is h_K = h_A + h_B with
// h_E(u) = sqrt(u^T M_E u) (M_E = R diag(rx^2, ry^2) R^T), and its boundary point of outer normal
// u is k(u) = s_A(u) + s_B(u), s_E(u) = M_E u / h_E(u). p(t) in K requires u . p(t) <= h_K(u)
// for every u, so each u facing the motion (u . w < 0) bounds the entry time from below:
//   t_in >= F(u) = (u . p0 - h_K(u)) / (-u . w),
// the time the path crosses K's supporting line of normal u, with equality at the normal of the
// entry point (ray casting against a Minkowski sum through support mappings: van den Bergen,
// "Ray Casting against General Convex Objects", 2004). In the frame (d, n) of the path
// (d = w / |w|, n = d turned +90 deg) take u(psi) = (-cos psi, sin psi), psi in [-pi/2, pi/2]:
//   f(psi) = n . k(psi) - sigma,   sigma = n . p0,
// rises monotonically from -h_K(n) - sigma to h_K(n) - sigma, with f'(psi) = cos psi (rho_A +
// rho_B), rho_E = det M_E / h_E^3 the radius of curvature of E at normal u; F rises while f < 0
// and falls after. So the line meets K iff |sigma| <= h_K(n) (closed form: the grazing decision),
// and the entry normal is the one root of f. It is found by Newton's method safeguarded by
// bisection (Numerical Recipes' rtsafe: bisect when the step leaves the bracket or fails to halve)
// on s = tan(psi / 2) in [-1, 1] (where that stalls near s = +-1, on 1 - |s|: EndChart), u taken
// unnormalised as (s^2 - 1, 2 s): no trigonometry in the loop. The search stops when the entry is
// certified to `kEntryTolerance`: F at every normal tried is a lower bound, and the chord between
// the boundary points of the bracket's ends, which lies in K, crosses the path at an upper bound.
// Where that bracket, roundings included, holds 0 or the horizon's reach (the verdict turns there)
// the search goes on, on an ellipse's flat side in its own frame (FlatSideChart).
// The exit is the entry of the reversed path.
// Double precision places the path relative to K only to the pair's extent E = |p0 . d| + h_K(n):
// p0, d, the normal's components and the ellipses' sin and cos carry roundings of ~eps, h_E(u) one
// of ~eps times the largest radius. Where the path meets K's boundary at an angle theta to its
// normal there, a shift of the path across itself moves the entry along it by tan theta times as
// much: the problem's conditioning, which grows as the path grazes K or runs nearly along a
// needle's flat side. The normal is resolved finely enough not to add to it: on a needle's flat
// side (axis ratio q) one ulp of the normal moves the support point by ~ulp q rx, and the chord
// and supporting lines of adjacent normals stay apart by up to ~ulp^2 q rx (fuzzer findings,
// q = 1.4e14: up to 0.25 eps E early, 1.5e-3 of the horizon, and met at 3.7e-7 rad, see
// CentreChart). The entry is early by at most kTranslationExtentTolerance * E / cos theta
// (tested to q = 1e18: 5 eps E), late by F's rounding only (measured up to 3 eps E / cos theta).
// No margin is taken off: an exact crossing (e.g. dyadic sizes, as the velocity gate's tests
// use) stays exact.
constexpr int kMaxEntrySteps = 100;  // samples per chart of the normal
// Width of the certified interval [m] relative to E, about the rounding of F.
constexpr double kEntryTolerance = 4.0 * std::numeric_limits<double>::epsilon();

/// An ellipse in the frame (d, n) of the path: its own x axis is (c, s), its y axis (-s, c).
struct AxesOnPath {
  double c, s;
  double rx2, ry2;
};

AxesOnPath axesOnPath(const Ellipse& e, const detail::SinCos& trig, const Eigen::Vector2d& d) {
  return {trig.cos * d.x() + trig.sin * d.y(), trig.sin * d.x() - trig.cos * d.y(),
          e.radius_x * e.radius_x, e.radius_y * e.radius_y};
}

/// For u = (ud, un) in the path frame, of any length L: h_E(u) (= L h_E(u / L)), the support point
/// s_E(u) = (k_d, k_n), and det M_E / h_E(u)^3 (= rho_E / L^3). From the ellipse's own axes, so
/// that a thin ellipse loses nothing to cancellation.
struct SupportOnPath {
  double h, k_d, k_n, curvature_radius_over_l3;
};

/// The same from u's components (ax, ay) along e's own axes.
SupportOnPath supportFromAxes(const AxesOnPath& e, double ax, double ay) {
  const double fx = e.rx2 * ax, fy = e.ry2 * ay;
  const double h = std::sqrt(fx * ax + fy * ay);
  const double inverse = 1.0 / h;
  return {h, (fx * e.c - fy * e.s) * inverse, (fx * e.s + fy * e.c) * inverse,
          e.rx2 * e.ry2 * (inverse * inverse * inverse)};
}

SupportOnPath supportOnPath(const AxesOnPath& e, double ud, double un) {
  return supportFromAxes(e, ud * e.c + un * e.s, un * e.c - ud * e.s);  // u . x axis, u . y axis
}

/// The pair in the path frame: p0 = (x0, sigma), both ellipses' axes.
struct PathPair {
  double x0, sigma;
  AxesOnPath a, b;

  PathPair reversed() const {
    return {-x0, -sigma, {-a.c, -a.s, a.rx2, a.ry2}, {-b.c, -b.s, b.rx2, b.ry2}};
  }
  /// K's boundary point of normal u (any length).
  Eigen::Vector2d boundaryPoint(double ud, double un) const {
    const SupportOnPath sa = supportOnPath(a, ud, un), sb = supportOnPath(b, ud, un);
    return {sa.k_d + sb.k_d, sa.k_n + sb.k_n};
  }
};

/// The entry normal u = (s^2 - 1, 2 s) (path frame, unnormalised) as a function of the search
/// variable v: its components -u . d = L cos psi and u . n = L sin psi, and L = |u| = 1 + s^2.
struct NormalOnPath {
  double cos_l, un, l;
};

/// A chart's sample: the normal, both ellipses' supports there, and df/dv over
/// (rho_A + rho_B) / L^3 (f'(psi) = cos psi (rho_A + rho_B), times dpsi/dv).
struct ChartSample {
  NormalOnPath u;
  SupportOnPath a, b;
  double slope_factor;
};

/// Both supports from the normal's path-frame components; on v = s or 1 - |s| (dpsi/ds = 2 / L)
/// df/ds = 2 cos_l L (rho_A + rho_B) / L^3.
ChartSample sampleOnPath(const PathPair& p, const NormalOnPath& u) {
  return {u, supportOnPath(p.a, -u.cos_l, u.un), supportOnPath(p.b, -u.cos_l, u.un),
          2.0 * u.cos_l * u.l};
}

/// The search starts on v = s itself (CentreChart), whose doubles are 1.1e-16 apart near s = +-1.
/// There u is within a small angle of +-n: the path meets K's boundary at a shallow angle theta to
/// its tangent, and the entry moves along the path by the normal's error times rho / cos theta
/// (rho: K's radius of curvature). On a needle's flat side (rho = q rx) a normal resolved to
/// 1.1e-16 rad left the supporting lines at the nearest normals crossing the path early by
/// ~rho 1e-32 / cos theta (fuzzer findings: axis ratio 1.4e14 met at 3.7e-7 rad, answers 6e-11 s
/// early where 1e-17 s was documented). So when the bracket holds adjacent doubles within
/// [1/2, 1] (or [-1, -1/2]) uncertified, the search goes on in v = 1 - |s| (EndChart), exact
/// there (Sterbenz), whose doubles near 0 resolve the normal's angle from +-n to eps of itself.
struct CentreChart {
  static constexpr bool kCentre = true;
  static constexpr double kDsDv = 1.0;
  static NormalOnPath at(double v) {
    const double v2 = v * v;
    return {1.0 - v2, 2.0 * v, 1.0 + v2};
  }
  ChartSample sample(const PathPair& p, double v) const { return sampleOnPath(p, at(v)); }
};

/// v = 1 - |s| from the end s = kEnd (+1 or -1): s = kEnd (1 - v).
template <int kEnd>
struct EndChart {
  static constexpr bool kCentre = false;
  static constexpr double kDsDv = -kEnd;
  static NormalOnPath at(double v) {
    const double cos_l = v * (2.0 - v);  // 1 - s^2 = (1 - s)(1 + s), the small factor v exact
    return {cos_l, 2.0 * kEnd * (1.0 - v), 2.0 - cos_l};
  }
  static double fromS(double s) { return 1.0 - kEnd * s; }  // exact for s in the end's half
  ChartSample sample(const PathPair& p, double v) const { return sampleOnPath(p, at(v)); }
};

/// Near an ellipse's flat side both charts above fail alike, whatever the path's angle: a normal
/// in the path frame is resolved to ~eps rad, and on the flat side of a needle of axis ratio q
/// (radius of curvature q radius_x) the supporting lines of the nearest normals lie up to
/// ~(radius_x eps)^2 / radius_y outside the side, more than the needle's thickness for q near
/// 1 / eps (fuzzer finding: a speck 3.4e-8 m off the flat side of a needle 1.7e9 m long, across a
/// path at 65 deg, covering 8e-14 m within the horizon, was called in contact). So the search can
/// go on in the ellipse's own frame: u = sigma (m + v l), m its minor axis and l its major axis
/// turned so that psi rises with v, sigma = +-1 facing the motion. The ellipse's support comes
/// from its own components (sigma, sigma v) exactly, resolving the normal to eps of its offset
/// from m; only the other ellipse's and the path's components are rotated (rounding ~eps).
struct FlatSideChart {
  static constexpr bool kCentre = false;
  static constexpr double kDsDv = 1.0;
  bool of_b;        // whose flat side: p.b's, else p.a's
  bool y_minor;     // the minor axis is the ellipse's y axis
  double sigma;     // +-1
  double m_d, m_n;  // m in the path frame
  double l_d, l_n;  // l in the path frame

  FlatSideChart(const PathPair& p, bool of_b_side) : of_b(of_b_side) {
    const AxesOnPath& e = of_b ? p.b : p.a;
    y_minor = e.ry2 <= e.rx2;
    // x axis (c, s), y axis (-s, c); m = y with l = x, or m = x with l = -y: m x l = -1, so u
    // turns clockwise as v rises, and psi (u = (-cos psi, sin psi)) rises.
    m_d = y_minor ? -e.s : e.c, m_n = y_minor ? e.c : e.s;
    l_d = y_minor ? e.c : e.s, l_n = y_minor ? e.s : -e.c;
    sigma = m_d < 0.0 ? 1.0 : -1.0;
  }
  /// The chart's v of a path-frame normal (ud, un), NaN unless it lies on sigma m's side.
  double of(double ud, double un) const {
    const double along = sigma * (ud * m_d + un * m_n);
    return along > 0.0 ? sigma * (ud * l_d + un * l_n) / along
                       : std::numeric_limits<double>::quiet_NaN();
  }
  ChartSample sample(const PathPair& p, double v) const {
    const double ud = sigma * (m_d + v * l_d), un = sigma * (m_n + v * l_n);
    const double length = std::sqrt(1.0 + v * v);
    // The ellipse's own components: m . u = sigma, l . u = sigma v (l = x, or l = -y).
    const AxesOnPath& e = of_b ? p.b : p.a;
    const SupportOnPath own =
        y_minor ? supportFromAxes(e, sigma * v, sigma) : supportFromAxes(e, sigma, -sigma * v);
    const SupportOnPath other = supportOnPath(of_b ? p.a : p.b, ud, un);
    // dpsi/dv = 1 / (1 + v^2): df/dv = (cos_l / L) (rho_A + rho_B) / L^2.
    return {{-ud, un, length}, of_b ? other : own, of_b ? own : other, -ud};
  }
};

/// The safeguarded Newton search for the root of f on the normal: the bracket [lo, hi] and the
/// iterate v in the current chart's variable, the boundary points k_lo, k_hi of the bracket's ends
/// where f < 0 and f > 0, and the best lower bound on the entry.
struct EntrySearch {
  EntrySearch(const PathPair& path, double reach_distance)
      : p(path),
        reach(reach_distance),
        k_lo(path.boundaryPoint(0.0, -1.0)),  // s = -1, 1 are the normals -n, n
        k_hi(path.boundaryPoint(0.0, 1.0)) {
    // Start where the path enters the disc of K's half-width across it: exact for two circles.
    const double width = k_hi.y();
    const double sine = std::clamp(p.sigma / width, -1.0, 1.0);
    // Strictly inside (-1, 1), where u . d < 0 and F is defined; the steps stay inside the bracket.
    constexpr double kInside = 1.0 - std::numeric_limits<double>::epsilon();
    v = std::clamp(sine / (1.0 + std::sqrt((1.0 - sine) * (1.0 + sine))), -kInside, kInside);
    tolerance = kEntryTolerance * (std::fabs(p.x0) + width);
  }

  const PathPair& p;
  double reach;
  Eigen::Vector2d k_lo, k_hi;
  double lo = -1.0, hi = 1.0, v, tolerance;
  double lower = -std::numeric_limits<double>::infinity();
  double last_step = 2.0;

  /// Steps on `Chart` until the entry is certified, beyond `reach`, or the bracket holds adjacent
  /// doubles (true: `lower` is the answer), except on the centre chart with the bracket within an
  /// end's half, where the end's chart resolves the normal further (false). At most
  /// kMaxEntrySteps samples on each chart.
  template <typename Chart>
  bool run(const Chart& chart = {}) {
    for (int step = 0; step < kMaxEntrySteps; ++step) {
      if (sample(chart)) return true;
      if (!advance<Chart>()) return !Chart::kCentre || (lo < 0.5 && hi > -0.5);
    }
    return true;
  }

  /// Goes on from the end s = kEnd, whose half holds the bracket. The bracket's ends were sampled
  /// on the centre chart, whose normals (1 - s^2 rounded) need not be the end chart's at the same
  /// v: both are sampled again, within the bracket of the normals s = kEnd, -kEnd (v = 0, 2),
  /// where f = +-h_K(n) - sigma on any chart.
  template <int kEnd>
  void runFromEnd() {
    using Chart = EndChart<kEnd>;
    const double from_lo = Chart::fromS(lo), from_hi = Chart::fromS(hi);
    lo = 0.0, hi = 2.0;
    for (const double start : {from_lo, from_hi}) {
      if (!(start > lo && start < hi)) continue;  // an end, or on the side of one sampled closer
      v = start;
      if (sample(Chart{})) return;
    }
    last_step = hi - lo;
    if (advance<Chart>()) run<Chart>();
  }

  /// Whether the verdict is still open: [lower, upper] (upper enlarged by its rounding) holds 0
  /// or `reach`.
  bool undecided() const {
    const double most = upper + upper_error;
    return (lower <= 0.0 && most > 0.0) || (lower <= reach && most > reach);
  }

  /// Goes on in the flat-side chart of p.a (of_b false) or p.b, when the bracket's normals lie
  /// within 1e-3 rad of its minor axis, facing the motion; else leaves the search as it is. The
  /// bracket's ends are moved into the chart, widened by their rounding, and sampled again.
  void runOnFlatSide(bool of_b) {
    const FlatSideChart chart(p, of_b);
    constexpr double kNear = 1e-3;
    const double v_lo = chart.of(u_lo_d, u_lo_n), v_hi = chart.of(u_hi_d, u_hi_n);
    if (!(std::fabs(v_lo) < kNear && std::fabs(v_hi) < kNear)) return;
    double margin = 16.0 * std::numeric_limits<double>::epsilon() *
                    (1.0 + std::max(std::fabs(v_lo), std::fabs(v_hi)));
    for (int widen = 0; widen < 8; ++widen, margin *= 16.0) {
      const double from = std::min(v_lo, v_hi) - margin, to = std::max(v_lo, v_hi) + margin;
      if (!(chart.sample(p, from).u.cos_l > 0.0 && chart.sample(p, to).u.cos_l > 0.0)) return;
      lo = -kNear, hi = kNear;  // wider than any sample: the two below set both ends
      v = from;
      if (sample(chart)) return;
      if (lo != from) continue;  // f >= 0 there: the root is below
      v = to;
      if (sample(chart)) return;
      if (hi != to) continue;
      last_step = hi - lo;
      if (advance<FlatSideChart>()) run(chart);
      return;
    }
  }

 private:
  double f = 0.0, slope = 0.0;  // at the last sample, df/dv
  double upper = std::numeric_limits<double>::infinity(), upper_error = 0.0;
  double u_lo_d = 0.0, u_lo_n = -1.0, u_hi_d = 0.0, u_hi_n = 1.0;  // normals at k_lo, k_hi

  /// Samples F and f at v: true when `lower` is the answer (certified to `tolerance`, beyond
  /// `reach`, or the boundary point on the path).
  template <typename Chart>
  bool sample(const Chart& chart) {
    const ChartSample q = chart.sample(p, v);
    const NormalOnPath& u = q.u;
    const SupportOnPath &sa = q.a, &sb = q.b;
    lower = std::max(lower, (u.un * p.sigma - u.cos_l * p.x0 - sa.h - sb.h) / u.cos_l);  // F |w|
    if (lower > reach) return true;
    const Eigen::Vector2d k(sa.k_d + sb.k_d, sa.k_n + sb.k_n);
    f = k.y() - p.sigma;
    if (f == 0.0) {  // k is the entry point
      lower = std::max(lower, k.x() - p.x0);
      upper = k.x() - p.x0;
      upper_error =
          8.0 * std::numeric_limits<double>::epsilon() * (k.lpNorm<1>() + std::fabs(p.x0));
      return true;
    }
    ((f < 0.0) == (Chart::kDsDv > 0.0) ? lo : hi) = v;  // f rises with s
    (f < 0.0 ? k_lo : k_hi) = k;
    (f < 0.0 ? u_lo_d : u_hi_d) = -u.cos_l;
    (f < 0.0 ? u_lo_n : u_hi_n) = u.un;
    const double chord_slope = (k_hi.x() - k_lo.x()) / (k_hi.y() - k_lo.y());
    upper = k_lo.x() + (p.sigma - k_lo.y()) * chord_slope - p.x0;
    // The boundary points carry roundings of ~eps times their size, which the chord's slope
    // against the path magnifies: on a needle's flat side they lie up to ~E away, and the chord
    // of path-frame normals put the path's entry 1e-7 m behind p0 though p0 was 3.4e-8 m outside
    // (fuzzer finding), so the verdict seemed settled and the pair touching at 0.
    upper_error = 8.0 * std::numeric_limits<double>::epsilon() *
                  (k_lo.lpNorm<1>() + k_hi.lpNorm<1>() + std::fabs(p.x0) + std::fabs(p.sigma)) *
                  (1.0 + std::fabs(chord_slope));
    slope = q.slope_factor * (sa.curvature_radius_over_l3 + sb.curvature_radius_over_l3);
    // Certified to `tolerance`, unless [lower, upper] holds 0 or `reach`, where the verdict turns
    // (p0 past K's entry or not, the entry within reach or not): E-relative, the tolerance can
    // exceed the gap to K by far (fuzzer finding: a needle 1.7e9 m long across the path, p0 3e-8 m
    // off its flat side, certified to 0.7 m and called in contact; the horizon ended 3.4e-14 m
    // on). There the search goes on as long as the normal resolves the entry.
    return upper - lower <= tolerance && !undecided();
  }

  /// The next v: a Newton step on f, or bisection when it leaves the bracket or fails to halve;
  /// false when the bracket holds adjacent doubles.
  template <typename Chart>
  bool advance() {
    double next = v - f / (slope * Chart::kDsDv);
    if (!(next > lo && next < hi) || std::fabs(next - v) > 0.5 * last_step) {
      next = lo + 0.5 * (hi - lo);
    }
    if (!(next > lo && next < hi)) return false;
    last_step = std::fabs(next - v);
    v = next;
    return true;
  }
};

/// The distance [m] along the path from p0 to where it enters K, at most
/// kTranslationExtentTolerance * (|x0| + h_K(n)) / cos theta less than the true one and never more
/// beyond rounding (theta: the angle between the path and K's normal at the entry), or any value
/// above `reach` [m] when the entry is beyond it. Precondition: the line meets K
/// (|sigma| <= h_K(n)).
double entryDistance(const PathPair& p, double reach) {
  EntrySearch search(p, reach);
  if (!search.run<CentreChart>()) {
    if (search.lo >= 0.5) {
      search.runFromEnd<1>();
    } else {
      search.runFromEnd<-1>();
    }
  }
  // Uncertified where the verdict turns: the normal may be resolved further on a flat side.
  for (const bool of_b : {false, true}) {
    if (search.lower > reach || !search.undecided()) break;
    search.runOnFlatSide(of_b);
  }
  return search.lower;
}

FirstContact translationContact(const Ellipse& a, const Ellipse& b, const Eigen::Vector2d& w,
                                double horizon) {
  if (w.x() == 0.0 && w.y() == 0.0) return {};  // same velocity: the t = 0 answer holds throughout
  // Bounding circles first: before the relative centre comes within R_a + R_b (enlarged against
  // rounding) no contact is possible, and a path that never does is clear without trigonometry.
  const Eigen::Vector2d p0 = b.center - a.center;
  const double slack = 4e-15 * p0.norm();
  const double outer = (boundingRadius(a) + boundingRadius(b)) * (1.0 + 1e-9) + slack;
  // w scaled by a power of two (exact), so that a tiny or subnormal relative velocity keeps its
  // full precision in its direction and speed. Each component is scaled itself: for a subnormal
  // w the factor 2^-ilogb alone overflows to inf (fuzzer finding).
  const int exponent = std::ilogb(std::max(std::fabs(w.x()), std::fabs(w.y())));
  const Eigen::Vector2d scaled(std::ldexp(w.x(), -exponent), std::ldexp(w.y(), -exponent));
  const double scaled_speed = scaled.norm();  // |w| = scaled_speed 2^exponent
  const Eigen::Vector2d d = scaled / scaled_speed;
  // Times in units of 2^-exponent s: a distance over scaled_speed, in range whatever the speed.
  // |w| itself, rounded to the subnormal grid, put the time off by up to 2^-1074 / |w| of itself
  // (6e-8 at 8e-317 m/s), and for a horizon near DBL_MAX the horizon enlarged against rounding
  // overflowed to inf: every entry past the bounding circles seemed within it (fuzzer finding).
  // scaled_horizon is subnormal, so rounded, only where the path reaches less than 1e-307 m.
  const double scaled_horizon = std::ldexp(horizon, exponent);
  const double x0 = p0.dot(d);
  const double sigma = d.x() * p0.y() - d.y() * p0.x();  // n . p0, n = (-d.y, d.x)
  if (std::fabs(sigma) > outer) return {};  // the line stays outside the circle of radius `outer`
  const double half_chord = std::sqrt((outer - std::fabs(sigma)) * (outer + std::fabs(sigma)));
  if (x0 > half_chord + slack) return {};  // moving away
  // A crossing within rounding of the horizon is at the horizon.
  const double late = scaled_horizon * (1.0 + 4.0 * std::numeric_limits<double>::epsilon());
  if ((-x0 - half_chord - slack) / scaled_speed > late) return {};
  const detail::SinCosPair trig = detail::sinCosPair(a.angle, b.angle);
  const PathPair path{x0, sigma, axesOnPath(a, trig.first, d), axesOnPath(b, trig.second, d)};
  if (std::fabs(sigma) > path.boundaryPoint(0.0, 1.0).y()) return {};  // the line misses K
  const double enter = entryDistance(path, late * scaled_speed) / scaled_speed;
  if (enter > 0.0) {
    if (enter > late) return {};
    // Back to seconds only below the horizon, where it cannot overflow.
    const double time = enter < scaled_horizon ? std::ldexp(enter, -exponent) : horizon;
    return {true, std::min(time, horizon)};
  }
  // The path enters K at or before p0, yet overlap() said apart at t = 0: p0 is beyond the exit
  // (moving away) or on the rim within rounding. The exit is the reversed path's entry.
  if (-entryDistance(path.reversed(), std::numeric_limits<double>::infinity()) < 0.0) return {};
  return {true, 0.0};  // touching "at 0": firstContact() moves it just after 0
}

// A total order on (ellipse, motion): the pair is always processed in this order, which makes
// firstContact exactly symmetric.
auto orderKey(const Ellipse& e, const Motion& m) {
  return std::make_tuple(e.center.x(), e.center.y(), e.radius_x, e.radius_y, e.angle,
                         m.velocity.x(), m.velocity.y(), m.angular_velocity);
}

std::string pathReason(const Ellipse& e, const Motion& m, double horizon) {
  const char* const names[2] = {"center.x", "center.y"};
  for (int i = 0; i < 2; ++i) {
    const double end = e.center[i] + m.velocity[i] * horizon;
    if (!coordinateOk(end)) {
      return std::string(names[i]) + " at the horizon = " + formatNumber(end) + " is outside [" +
             formatNumber(-kMaxCoordinate) + ", " + formatNumber(kMaxCoordinate) + "] m";
    }
  }
  return {};
}

}  // namespace

std::string invalidVelocityReason(const Motion& m, double horizon,
                                  const VelocityFieldNames& names) {
  const char* const components[2] = {names.x, names.y};
  for (int i = 0; i < 2; ++i) {
    const double v = m.velocity[i];
    if (!std::isfinite(v)) {
      return std::string(components[i]) + " = " + formatNumber(v) + " must be finite";
    }
    if (std::fabs(v) > kMaxSpeed) {
      return std::string(components[i]) + " = " + formatNumber(v) + " is outside [" +
             formatNumber(-kMaxSpeed) + ", " + formatNumber(kMaxSpeed) + "] m/s";
    }
  }
  const double w = m.angular_velocity;
  // Called for every obstacle a check or the gate looks at: no string unless there is a problem.
  const char* const angular = names.angular;
  if (!std::isfinite(w)) return angular + (" = " + formatNumber(w)) + " must be finite";
  if (std::fabs(w) > kMaxAngularVelocity) {
    return angular + (" = " + formatNumber(w)) + " is outside [" +
           formatNumber(-kMaxAngularVelocity) + ", " + formatNumber(kMaxAngularVelocity) +
           "] rad/s";
  }
  if (std::fabs(w) * horizon > kMaxTurn) {
    return angular + (" = " + formatNumber(w)) + " turns more than " + formatNumber(kMaxTurn) +
           " rad within horizon = " + formatNumber(horizon) + " s";
  }
  return {};
}

std::string invalidMotionReason(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                                const Motion& motion_b, double horizon) {
  if (std::string r = invalidReason(a); !r.empty()) return "ellipse 1: " + r;
  if (std::string r = invalidReason(b); !r.empty()) return "ellipse 2: " + r;
  if (!std::isfinite(horizon)) return "horizon = " + formatNumber(horizon) + " must be finite";
  if (horizon < 0.0) return "horizon = " + formatNumber(horizon) + " must be >= 0";
  if (std::string r = invalidVelocityReason(motion_a, horizon); !r.empty()) {
    return "motion 1: " + r;
  }
  if (std::string r = invalidVelocityReason(motion_b, horizon); !r.empty()) {
    return "motion 2: " + r;
  }
  if (std::string r = pathReason(a, motion_a, horizon); !r.empty()) return "motion 1: " + r;
  if (std::string r = pathReason(b, motion_b, horizon); !r.empty()) return "motion 2: " + r;
  return {};
}

std::string invalidMotionReason(const Ellipse& e, const Motion& motion, double horizon) {
  if (std::string r = invalidReason(e); !r.empty()) return r;
  if (std::string r = invalidVelocityReason(motion, horizon); !r.empty()) return r;
  return pathReason(e, motion, horizon);
}

FirstContact firstContact(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                          const Motion& motion_b, double horizon) {
  if (orderKey(b, motion_b) < orderKey(a, motion_a)) {
    return firstContact(b, motion_b, a, motion_a, horizon);
  }
  if (overlap(a, b)) return {true, 0.0};
  if (!(horizon > 0.0)) return {};
  // A spinning circle sweeps nothing: such pairs translate, and the exact method applies.
  const bool a_turns = motion_a.angular_velocity != 0.0 && a.radius_x != a.radius_y;
  const bool b_turns = motion_b.angular_velocity != 0.0 && b.radius_x != b.radius_y;
  FirstContact contact;
  if (!a_turns && !b_turns) {
    contact = translationContact(a, b, motion_b.velocity - motion_a.velocity, horizon);
  } else {
    contact =
        detail::rotatingContact(detail::rotatingPair(a, motion_a.velocity, Eigen::Vector2d::Zero(),
                                                     motion_a.angular_velocity, b, motion_b),
                                horizon);
  }
  // overlap() said they are apart at t = 0; a pair whose contact scale there is within rounding
  // of 1 can still be found touching "at 0" by the gauge (fuzzer finding).
  return detail::apartAtZero(contact, horizon);
}

}  // namespace ellipse_collision::core
