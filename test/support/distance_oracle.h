#pragma once

// Independent oracle for the minimum distance between two separated ellipses, shared by
// test_distance and bench_distance. It works on the primal problem (points on the rims) while
// distance() works on the support-function dual:
//  1. sample the rim of `a` at kRimSamples eccentric angles and measure, in long double, the exact
//     distance from each sample to `b` (the 1D foot-point equation, solved by safeguarded Newton);
//  2. refine the best few local minima of those samples in __float128 by a damped Newton iteration
//     on D(t, tau) = |P_a(t) - P_b(tau)|^2 over both eccentric angles, and keep the smallest.
// Header-only so that the benchmark can use it without another library target.

#include <quadmath.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {
namespace test {

using quad = __float128;

/// Minimum distance found by the oracle, in quad precision.
struct OracleDistance {
  quad distance{0};   ///< [m]
  quad ax{0}, ay{0};  ///< witness point on the rim of a [m]
  quad bx{0}, by{0};  ///< witness point on the rim of b [m]
};

namespace oracle_detail {

// Fine enough that the sample next to the global minimum lies in its Newton basin even on the
// flat side of a 1e3:1 ellipse; refinement fixes everything below the grid spacing.
constexpr int kRimSamples = 4096;
// Local minima of the samples refined in quad: the global one is among them unless two distinct
// basins differ by less than the sampling error, and then refining several settles it.
constexpr int kRefinedMinima = 4;
constexpr int kMaxNewtonIterations = 200;

inline quad quadPi() { return acosq(static_cast<quad>(-1)); }

/// Distance from the point (y0, y1), given in the ellipse's own frame, to the ellipse with
/// semi-axes e0, e1; 0 when the point is inside. Solves the foot-point equation
///   F(s) = (e0 y0 / (s + e0^2))^2 + (e1 y1 / (s + e1^2))^2 - 1 = 0,  s > -min(e0, e1)^2,
/// on which F decreases, by Newton safeguarded by bisection.
inline long double pointToEllipse(long double e0, long double e1, long double y0, long double y1) {
  using ld = long double;
  y0 = std::fabs(y0);
  y1 = std::fabs(y1);
  if ((y0 / e0) * (y0 / e0) + (y1 / e1) * (y1 / e1) <= 1.0L) return 0.0L;
  const ld a0 = e0 * y0, a1 = e1 * y1;
  const ld e02 = e0 * e0, e12 = e1 * e1;
  // One term alone reaches 1 at lo; the sum of both is below 1 at hi.
  ld lo = std::max(a0 - e02, a1 - e12);
  ld hi = std::sqrt(a0 * a0 + a1 * a1) - std::min(e02, e12);
  ld s = lo;
  for (int i = 0; i < 200 && hi > lo; ++i) {
    const ld r0 = a0 / (s + e02), r1 = a1 / (s + e12);
    const ld f = r0 * r0 + r1 * r1 - 1.0L;
    if (f > 0.0L) {
      lo = s;
    } else if (f < 0.0L) {
      hi = s;
    } else {
      break;
    }
    const ld df = -2.0L * (r0 * r0 / (s + e02) + r1 * r1 / (s + e12));
    ld next = s - f / df;
    if (!(next > lo && next < hi)) next = 0.5L * (lo + hi);
    if (next == s) break;
    s = next;
  }
  const ld x0 = e02 * y0 / (s + e02), x1 = e12 * y1 / (s + e12);
  return std::hypot(y0 - x0, y1 - x1);
}

/// One ellipse in quad precision, relative to an origin: P(t) = c + R (rx cos t, ry sin t).
struct QuadEllipse {
  quad cx, cy, rx, ry, cos_angle, sin_angle;

  void at(quad t, quad* px, quad* py, quad* tx, quad* ty) const {
    quad s, c;
    sincosq(t, &s, &c);
    const quad lx = rx * c, ly = ry * s;   // local point
    const quad dx = -rx * s, dy = ry * c;  // local tangent
    *px = cx + cos_angle * lx - sin_angle * ly;
    *py = cy + sin_angle * lx + cos_angle * ly;
    *tx = cos_angle * dx - sin_angle * dy;
    *ty = sin_angle * dx + cos_angle * dy;
  }
};

inline QuadEllipse quadEllipse(const Ellipse& e, quad ox, quad oy) {
  const quad angle = e.angle;
  return {static_cast<quad>(e.center.x()) - ox,
          static_cast<quad>(e.center.y()) - oy,
          e.radius_x,
          e.radius_y,
          cosq(angle),
          sinq(angle)};
}

/// Damped Newton on D(t, u) = |P_a(t) - P_b(u)|^2 from (t, u). Near a minimum of two separated
/// convex rims the Hessian is positive definite; a Levenberg term covers the rest.
inline OracleDistance refine(const QuadEllipse& ea, const QuadEllipse& eb, quad t, quad u) {
  auto evaluate = [&](quad tt, quad uu, quad g[2], quad hess[3], quad* pa, quad* pb) {
    quad ax, ay, atx, aty, bx, by, btx, bty;
    ea.at(tt, &ax, &ay, &atx, &aty);
    eb.at(uu, &bx, &by, &btx, &bty);
    const quad dx = ax - bx, dy = ay - by;
    if (g != nullptr) {
      // P'' = -(P - c) for the eccentric-angle parametrisation.
      g[0] = 2 * (dx * atx + dy * aty);
      g[1] = -2 * (dx * btx + dy * bty);
      hess[0] = 2 * (atx * atx + aty * aty) - 2 * (dx * (ax - ea.cx) + dy * (ay - ea.cy));
      hess[1] = -2 * (atx * btx + aty * bty);
      hess[2] = 2 * (btx * btx + bty * bty) + 2 * (dx * (bx - eb.cx) + dy * (by - eb.cy));
    }
    if (pa != nullptr) {
      pa[0] = ax, pa[1] = ay, pb[0] = bx, pb[1] = by;
    }
    return dx * dx + dy * dy;
  };

  quad g[2], hess[3], pa[2], pb[2];
  quad value = evaluate(t, u, g, hess, pa, pb);
  quad mu = 0;
  for (int i = 0; i < kMaxNewtonIterations; ++i) {
    bool improved = false;
    quad dt = 0, du = 0;
    for (int attempt = 0; attempt < 80 && !improved; ++attempt) {
      const quad h0 = hess[0] + mu, h2 = hess[2] + mu;
      const quad det = h0 * h2 - hess[1] * hess[1];
      if (h0 > 0 && det > 0) {
        dt = -(h2 * g[0] - hess[1] * g[1]) / det;
        du = -(h0 * g[1] - hess[1] * g[0]) / det;
        const quad trial = evaluate(t + dt, u + du, nullptr, nullptr, nullptr, nullptr);
        if (trial <= value) improved = true;
      }
      if (!improved) {
        const quad scale = fabsq(hess[0]) + fabsq(hess[2]) + fabsq(hess[1]);
        mu = mu == 0 ? scale * static_cast<quad>(1e-8) : mu * 8;
      }
    }
    if (!improved) break;
    t += dt;
    u += du;
    mu /= 16;
    if (mu < fabsq(hess[0] + hess[2]) * static_cast<quad>(1e-30)) mu = 0;
    value = evaluate(t, u, g, hess, pa, pb);
    if (fabsq(dt) + fabsq(du) < static_cast<quad>(1e-32)) break;
  }
  OracleDistance result;
  result.distance = sqrtq(value);
  result.ax = pa[0], result.ay = pa[1], result.bx = pb[0], result.by = pb[1];
  return result;
}

}  // namespace oracle_detail

/// Minimum distance between two separated ellipses, computed independently of distance().
/// Throws std::invalid_argument when a sample of a's rim lies inside b (the pair overlaps).
inline OracleDistance oracleDistance(const Ellipse& a, const Ellipse& b) {
  using namespace oracle_detail;
  using ld = long double;
  // Work relative to a's centre so that large coordinates cost no precision.
  const quad ox = a.center.x(), oy = a.center.y();
  const QuadEllipse ea = quadEllipse(a, ox, oy);
  const QuadEllipse eb = quadEllipse(b, ox, oy);

  const ld ca = std::cos(static_cast<ld>(a.angle)), sa = std::sin(static_cast<ld>(a.angle));
  const ld cb = std::cos(static_cast<ld>(b.angle)), sb = std::sin(static_cast<ld>(b.angle));
  const ld bcx = static_cast<ld>(eb.cx), bcy = static_cast<ld>(eb.cy);
  const ld two_pi = 2.0L * std::acos(-1.0L);
  std::vector<ld> dist(kRimSamples);
  for (int k = 0; k < kRimSamples; ++k) {
    const ld t = two_pi * k / kRimSamples;
    const ld lx = a.radius_x * std::cos(t), ly = a.radius_y * std::sin(t);
    const ld px = ca * lx - sa * ly - bcx, py = sa * lx + ca * ly - bcy;
    dist[k] = pointToEllipse(b.radius_x, b.radius_y, cb * px + sb * py, -sb * px + cb * py);
    if (dist[k] == 0.0L) throw std::invalid_argument("oracleDistance: the ellipses overlap");
  }

  std::vector<std::pair<ld, int>> minima;
  for (int k = 0; k < kRimSamples; ++k) {
    const ld prev = dist[(k + kRimSamples - 1) % kRimSamples];
    const ld next = dist[(k + 1) % kRimSamples];
    if (dist[k] <= prev && dist[k] <= next) minima.emplace_back(dist[k], k);
  }
  std::sort(minima.begin(), minima.end());
  if (minima.size() > static_cast<size_t>(kRefinedMinima)) minima.resize(kRefinedMinima);

  OracleDistance best;
  bool have_best = false;
  for (const auto& [value, k] : minima) {
    const ld t = two_pi * k / kRimSamples;
    // b's eccentric angle of the foot point, from the direction of the sample seen from b.
    const ld lx = a.radius_x * std::cos(t), ly = a.radius_y * std::sin(t);
    const ld px = ca * lx - sa * ly - bcx, py = sa * lx + ca * ly - bcy;
    const ld qx = cb * px + sb * py, qy = -sb * px + cb * py;
    const ld u = std::atan2(qy / b.radius_y, qx / b.radius_x);
    OracleDistance candidate = refine(ea, eb, static_cast<quad>(t), static_cast<quad>(u));
    // Refinement starts at (near) a sample, so it can only improve on it.
    if (candidate.distance > static_cast<quad>(value) * (1 + static_cast<quad>(1e-12))) continue;
    if (!have_best || candidate.distance < best.distance) {
      best = candidate;
      have_best = true;
    }
  }
  if (!have_best) throw std::runtime_error("oracleDistance: refinement failed");
  best.ax += ox, best.ay += oy, best.bx += ox, best.by += oy;
  return best;
}

/// Distance from (x, y) to the rim of `e` [m], to first order in the (tiny) offset: |F - 1| /
/// |grad F| with F(p) = (p_x / rx)^2 + (p_y / ry)^2 in the ellipse's frame, evaluated in quad.
inline quad distanceToRim(const Ellipse& e, quad x, quad y) {
  const quad angle = e.angle;
  const quad c = cosq(angle), s = sinq(angle);
  const quad dx = x - static_cast<quad>(e.center.x()), dy = y - static_cast<quad>(e.center.y());
  const quad lx = c * dx + s * dy, ly = -s * dx + c * dy;
  const quad rx2 = static_cast<quad>(e.radius_x) * e.radius_x;
  const quad ry2 = static_cast<quad>(e.radius_y) * e.radius_y;
  const quad f = lx * lx / rx2 + ly * ly / ry2 - 1;
  const quad gx = 2 * lx / rx2, gy = 2 * ly / ry2;
  return fabsq(f) / sqrtq(gx * gx + gy * gy);
}

}  // namespace test
}  // namespace ellipse_collision::core
