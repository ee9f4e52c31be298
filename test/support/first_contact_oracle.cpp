#include "first_contact_oracle.h"

#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ellipse_collision::core {
namespace test {
namespace {

using quad = __float128;

inline void sinCos(quad x, quad* s, quad* c) { sincosq(x, s, c); }
inline void sinCos(long double x, long double* s, long double* c) { *s = sinl(x), *c = cosl(x); }
inline quad root(quad x) { return sqrtq(x); }
inline long double root(long double x) { return sqrtl(x); }
inline quad absolute(quad x) { return fabsq(x); }
inline long double absolute(long double x) { return fabsl(x); }
template <typename T> T pi() { return static_cast<T>(acosq(static_cast<quad>(-1))); }

// A centred ellipse by its axis directions and squared radii.
template <typename T>
struct Shape {
  T c, s, rx2, ry2;
  // h(u) and the support point s(u) = (rx^2 (u.ex) ex + ry^2 (u.ey) ey) / h(u).
  void support(T ux, T uy, T* px, T* py, T* h) const {
    const T ax = c * ux + s * uy, ay = c * uy - s * ux;
    *h = root(rx2 * ax * ax + ry2 * ay * ay);
    const T fx = rx2 * ax / *h, fy = ry2 * ay / *h;
    *px = c * fx - s * fy;
    *py = s * fx + c * fy;
  }
};

template <typename T>
Shape<T> shapeAt(const Ellipse& e, const Motion& m, T t) {
  T s, c;
  sinCos(static_cast<T>(e.angle) + static_cast<T>(m.angular_velocity) * t, &s, &c);
  const T rx = e.radius_x, ry = e.radius_y;
  return {c, s, rx * rx, ry * ry};
}

template <typename T>
struct Sum {
  Shape<T> a, b;
  // The boundary point k(phi) of K = A + B with outer normal (cos phi, sin phi), and h_K.
  void at(T phi, T* kx, T* ky, T* h) const {
    T s, c;
    sinCos(phi, &s, &c);
    T ax, ay, ha, bx, by, hb;
    a.support(c, s, &ax, &ay, &ha);
    b.support(c, s, &bx, &by, &hb);
    *kx = ax + bx, *ky = ay + by, *h = ha + hb;
  }
  // The phi in [lo, hi] where m . k(phi) - level changes sign (it increases from lo to hi).
  T crossing(T lo, T hi, T mx, T my, T level) const {
    for (int i = 0; i < 160; ++i) {
      const T mid = (lo + hi) / 2;
      if (!(mid > lo && mid < hi)) break;
      T kx, ky, h;
      at(mid, &kx, &ky, &h);
      (mx * kx + my * ky - level < 0 ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  }
  // Gauge of K at p: p . u / h_K(u) at the normal u of the boundary point on the ray of p. Any u
  // gives a lower bound and that one the gauge (the dual form), so an error in u costs only its
  // square. The primal form |p|^2 / (p . k) took the error of k along the boundary at first
  // order: along a needle's flat side, which k sweeps within r / R of the normal's angle, the
  // rounding of u moved it by ~eps R^2 / r, and an axis ratio of 1e14 left the quad gauge 1e-8
  // off and the long double one unusable.
  T gauge(T px, T py) const {
    const T norm = root(px * px + py * py);
    if (norm == 0) return 0;
    const T mx = -py / norm, my = px / norm;  // m = rot90(p^)
    const T phi_m = atan2l(static_cast<long double>(my), static_cast<long double>(mx));
    // On [phi_m - pi, phi_m] the normal turns from -m through p^ to m: m . k increases through 0.
    const T phi = crossing(phi_m - pi<T>(), phi_m, mx, my, 0);
    T kx, ky, h, s, c;
    at(phi, &kx, &ky, &h);
    sinCos(phi, &s, &c);
    return (px * c + py * s) / h;
  }
};

template <typename T>
Sum<T> sumAt(const Ellipse& a, const Motion& ma, const Ellipse& b, const Motion& mb, T t) {
  return {shapeAt(a, ma, t), shapeAt(b, mb, t)};
}

template <typename T>
T gaugeAt(const Ellipse& a, const Motion& ma, const Ellipse& b, const Motion& mb, T t) {
  const T px = (static_cast<T>(b.center.x()) - a.center.x()) +
               (static_cast<T>(mb.velocity.x()) - ma.velocity.x()) * t;
  const T py = (static_cast<T>(b.center.y()) - a.center.y()) +
               (static_cast<T>(mb.velocity.y()) - ma.velocity.y()) * t;
  return sumAt(a, ma, b, mb, t).gauge(px, py);
}

OracleFirstContact translation(const Ellipse& a, const Motion& ma, const Ellipse& b,
                               const Motion& mb, quad horizon) {
  OracleFirstContact r;
  const Sum<quad> k = sumAt<quad>(a, ma, b, mb, 0);
  const quad px = static_cast<quad>(b.center.x()) - a.center.x();
  const quad py = static_cast<quad>(b.center.y()) - a.center.y();
  const quad wx = static_cast<quad>(mb.velocity.x()) - ma.velocity.x();
  const quad wy = static_cast<quad>(mb.velocity.y()) - ma.velocity.y();
  const quad g0 = k.gauge(px, py);
  if (g0 <= 1) return {true, 0, g0};
  const quad w2 = wx * wx + wy * wy;
  if (w2 == 0) return {false, 0, g0};
  const quad wn = sqrtq(w2);
  const quad nx = -wy / wn, ny = wx / wn;
  const quad sigma = nx * px + ny * py;  // the line is {x : n . x = sigma}
  const quad phi_n = atan2q(ny, nx);
  quad kx, ky, hn;
  k.at(phi_n, &kx, &ky, &hn);
  const quad s_line = fabsq(sigma) / hn;
  // Tangency point of s_line K with the line, and its time.
  quad qx, qy, hq;
  k.at(sigma >= 0 ? phi_n : phi_n + pi<quad>(), &qx, &qy, &hq);
  const quad t_min = ((s_line * qx - px) * wx + (s_line * qy - py) * wy) / w2;
  if (t_min >= 0 && t_min <= horizon) {
    r.min_scale = s_line;
  } else if (t_min < 0) {
    r.min_scale = g0;
  } else {
    r.min_scale = gaugeAt<quad>(a, ma, b, mb, horizon);
  }
  if (s_line >= 1) return {false, 0, r.min_scale};
  // Entry and exit: on [phi_n - pi, phi_n] n . k increases from -h to h, on [phi_n, phi_n + pi]
  // it decreases (cross with the negated normal).
  const quad phi1 = k.crossing(phi_n - pi<quad>(), phi_n, nx, ny, sigma);
  const quad phi2 = k.crossing(phi_n, phi_n + pi<quad>(), -nx, -ny, -sigma);
  quad t_first = 0, phi_first = 0;
  bool first = true;
  for (quad phi : {phi1, phi2}) {
    k.at(phi, &kx, &ky, &hn);
    const quad t = ((kx - px) * wx + (ky - py) * wy) / w2;
    if (first || t < t_first) t_first = t, phi_first = phi;
    first = false;
  }
  if (t_first < 0 || t_first > horizon) return {false, 0, r.min_scale};
  quad sin_first, cos_first;
  sinCos(phi_first, &sin_first, &cos_first);
  return {true, t_first, r.min_scale, fabsq(cos_first * wx + sin_first * wy) / wn};
}

OracleFirstContact rotation(const Ellipse& a, const Motion& ma, const Ellipse& b,
                            const Motion& mb, double horizon, int samples) {
  using ld = long double;
  ld prev_t = 0;
  const ld g0 = gaugeAt<ld>(a, ma, b, mb, 0);
  quad g0q = gaugeAt<quad>(a, ma, b, mb, 0);
  if (g0q <= 1) return {true, 0, g0q};
  ld min_scale = g0;
  for (int i = 1; i <= samples; ++i) {
    const ld t = static_cast<ld>(horizon) * i / samples;
    const ld g = gaugeAt<ld>(a, ma, b, mb, t);
    min_scale = std::min(min_scale, g);
    if (g <= 1) {
      quad lo = prev_t, hi = t;
      if (gaugeAt<quad>(a, ma, b, mb, hi) > 1) {  // long double rounding: keep scanning
        prev_t = t;
        continue;
      }
      for (int k = 0; k < 120; ++k) {
        const quad mid = (lo + hi) / 2;
        if (!(mid > lo && mid < hi)) break;
        (gaugeAt<quad>(a, ma, b, mb, mid) <= 1 ? hi : lo) = mid;
      }
      return {true, hi, static_cast<quad>(min_scale)};
    }
    prev_t = t;
  }
  return {false, 0, static_cast<quad>(min_scale)};
}

template <typename T>
T cast(quad x) {
  return static_cast<T>(x);
}

// The displacement c(t) - c0 of a rigid motion (OracleRigidMotion) at t.
template <typename T>
void displacement(const OracleRigidMotion& m, T t, T* dx, T* dy) {
  const T vx = cast<T>(m.vx), vy = cast<T>(m.vy), ux = cast<T>(m.ux), uy = cast<T>(m.uy);
  const T w = cast<T>(m.turn_rate);
  T along = t, across = 0;  // sin(W t) / W and (1 - cos(W t)) / W, written without cancellation
  if (w != 0) {
    T s, c, s_half, c_half;
    sinCos(w * t, &s, &c);
    sinCos(w * t / 2, &s_half, &c_half);
    along = s / w;
    across = 2 * s_half * s_half / w;
  }
  *dx = vx * t + along * ux - across * uy;
  *dy = vy * t + along * uy + across * ux;
}

template <typename T>
T rigidGaugeAt(const Ellipse& a, const OracleRigidMotion& ma, const Ellipse& b,
               const OracleRigidMotion& mb, T t) {
  T dax, day, dbx, dby;
  displacement(ma, t, &dax, &day);
  displacement(mb, t, &dbx, &dby);
  const T px = cast<T>(mb.x - ma.x) + (dbx - dax);
  const T py = cast<T>(mb.y - ma.y) + (dby - day);
  const auto shape = [t](const Ellipse& e, const OracleRigidMotion& m) {
    T s, c;
    sinCos(cast<T>(m.angle) + cast<T>(m.turn_rate) * t, &s, &c);
    const T rx = e.radius_x, ry = e.radius_y;
    return Shape<T>{c, s, rx * rx, ry * ry};
  };
  return Sum<T>{shape(a, ma), shape(b, mb)}.gauge(px, py);
}

}  // namespace

OracleRigidMotion oracleMotionOf(const Ellipse& e, const Motion& m) {
  OracleRigidMotion r;
  r.x = e.center.x(), r.y = e.center.y(), r.angle = e.angle;
  r.vx = m.velocity.x(), r.vy = m.velocity.y();
  r.turn_rate = m.angular_velocity;
  return r;
}

Ellipse oraclePoseAt(const Ellipse& e, const OracleRigidMotion& m, quad t) {
  quad dx, dy;
  displacement(m, t, &dx, &dy);
  Ellipse at = e;
  at.center = {static_cast<double>(m.x + dx), static_cast<double>(m.y + dy)};
  at.angle = static_cast<double>(m.angle + m.turn_rate * t);
  return at;
}

Eigen::Vector2d oracleVelocityAt(const OracleRigidMotion& m, quad t) {
  quad s, c;
  sincosq(m.turn_rate * t, &s, &c);
  return {static_cast<double>(m.vx + c * m.ux - s * m.uy),
          static_cast<double>(m.vy + s * m.ux + c * m.uy)};
}

quad oracleRigidScaleAt(const Ellipse& a, const OracleRigidMotion& ma, const Ellipse& b,
                        const OracleRigidMotion& mb, quad t) {
  return rigidGaugeAt<quad>(a, ma, b, mb, t);
}

OracleGrazingPass oracleGrazingPass(Ellipse& a, const OracleRigidMotion& ma, Ellipse& b,
                                    const OracleRigidMotion& mb, double horizon, double target,
                                    int samples) {
  using ld = long double;
  const auto scaleAt = [&](quad t) { return rigidGaugeAt<quad>(a, ma, b, mb, t); };
  std::vector<ld> scanned(samples + 1);
  int smallest = 0;
  for (int i = 0; i <= samples; ++i) {
    scanned[i] = rigidGaugeAt<ld>(a, ma, b, mb, static_cast<ld>(horizon) * i / samples);
    if (scanned[i] < scanned[smallest]) smallest = i;
  }
  OracleGrazingPass pass;
  if (smallest == 0 || smallest == samples) return pass;
  for (int i = 0; i < samples; ++i) {
    if (i < smallest ? !(scanned[i + 1] < scanned[i]) : !(scanned[i + 1] > scanned[i])) {
      return pass;
    }
  }
  // Golden section on the samples either side of the smallest.
  const quad step = static_cast<quad>(horizon) / samples;
  quad lo = step * (smallest - 1), hi = step * (smallest + 1);
  const quad ratio = (sqrtq(5) - 1) / 2;
  quad x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  quad f1 = scaleAt(x1), f2 = scaleAt(x2);
  // The scale is quadratic about its smallest: a time within 1e-18 of the horizon gives the
  // scale to ~1e-36, and the bisection below gives the contact to 2^-64 of the dip.
  for (int k = 0; k < 120 && hi - lo > static_cast<quad>(1e-18) * horizon; ++k) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo), f1 = scaleAt(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo), f2 = scaleAt(x2);
    }
  }
  pass.time = f1 < f2 ? x1 : x2;
  const quad radius_scale = (f1 < f2 ? f1 : f2) / static_cast<quad>(target);
  for (Ellipse* e : {&a, &b}) {
    e->radius_x = static_cast<double>(e->radius_x * radius_scale);
    e->radius_y = static_cast<double>(e->radius_y * radius_scale);
  }
  pass.found = true;
  pass.scale = scaleAt(pass.time);
  pass.contact = pass.scale <= 1;
  if (pass.contact) {
    quad before = 0, after = pass.time;
    if (scaleAt(before) <= 1) return pass.contact_time = 0, pass;
    for (int k = 0; k < 64; ++k) {
      const quad mid = (before + after) / 2;
      (scaleAt(mid) <= 1 ? after : before) = mid;
    }
    pass.contact_time = after;
  }
  return pass;
}

quad oracleScaleAt(const Ellipse& a, const Motion& ma, const Ellipse& b, const Motion& mb, quad t) {
  return gaugeAt<quad>(a, ma, b, mb, t);
}

OracleFirstContact oracleFirstContact(const Ellipse& a, const Motion& ma, const Ellipse& b,
                                      const Motion& mb, double horizon, int rotation_samples) {
  if (ma.angular_velocity == 0 && mb.angular_velocity == 0) {
    return translation(a, ma, b, mb, horizon);
  }
  return rotation(a, ma, b, mb, horizon, rotation_samples);
}

}  // namespace test
}  // namespace ellipse_collision::core
