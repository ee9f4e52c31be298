#include "contact_scale_oracle.h"

#include <quadmath.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ellipse_collision::core {
namespace test {
namespace {

using quad = __float128;

// f(phi) is unimodal on the circle, so a grid this fine only has to land next to the peak; the
// quad refinement does the rest.
constexpr int kSamples = 4096;

// Bracket half-width in samples around the best sample: +-1 suffices for a unimodal function,
// the extra sample absorbs long double rounding when neighbours are nearly equal.
constexpr int kBracketSamples = 2;

// Stop the bisection when the bracket on phi is this narrow [rad]: t* then has a relative error
// of order (width)^2 times the peak curvature, far below quad epsilon.
const quad kPhiTolerance = static_cast<quad>(1e-28);

constexpr int kMaxBisections = 400;

const quad kQuadPi = acosq(static_cast<quad>(-1));

/// An ellipse's axes for its support function h(u)^2 = rx^2 (u . e_x)^2 + ry^2 (u . e_y)^2, with
/// e_x = (c, s), e_y = (-s, c). A sum of squares keeps full relative precision for thin ellipses,
/// where the expanded matrix S = R diag(rx^2, ry^2) R^T loses a factor of (rx / ry)^2.
template <typename T>
struct Axes {
  T c, s, rx2, ry2;

  T supportSquared(T ux, T uy) const {
    const T along_x = c * ux + s * uy, along_y = c * uy - s * ux;
    return rx2 * along_x * along_x + ry2 * along_y * along_y;
  }

  /// v^T S u.
  T bilinear(T vx, T vy, T ux, T uy) const {
    return rx2 * (c * vx + s * vy) * (c * ux + s * uy) +
           ry2 * (c * vy - s * vx) * (c * uy - s * ux);
  }
};

Axes<quad> quadAxes(const Ellipse& e) {
  const quad rx = e.radius_x, ry = e.radius_y;
  return {cosq(static_cast<quad>(e.angle)), sinq(static_cast<quad>(e.angle)), rx * rx, ry * ry};
}

template <typename T>
Axes<T> narrow(const Axes<quad>& a) {
  return {static_cast<T>(a.c), static_cast<T>(a.s), static_cast<T>(a.rx2), static_cast<T>(a.ry2)};
}

struct Problem {
  Axes<quad> a, b;
  quad dx, dy;
};

/// (u . d) / (h_a(u) + h_b(u)) at u = (cos phi, sin phi).
quad ratioAt(const Problem& p, quad phi) {
  quad s, c;
  sincosq(phi, &s, &c);
  return (c * p.dx + s * p.dy) /
         (sqrtq(p.a.supportSquared(c, s)) + sqrtq(p.b.supportSquared(c, s)));
}

/// Sign-carrying numerator of d/dphi of ratioAt: N' D - N D' with N = u . d, D = h_a + h_b.
quad slopeNumeratorAt(const Problem& p, quad phi) {
  quad s, c;
  sincosq(phi, &s, &c);
  const quad px = -s, py = c;  // du/dphi
  const quad ha = sqrtq(p.a.supportSquared(c, s));
  const quad hb = sqrtq(p.b.supportSquared(c, s));
  const quad dha = p.a.bilinear(px, py, c, s) / ha;
  const quad dhb = p.b.bilinear(px, py, c, s) / hb;
  const quad n = c * p.dx + s * p.dy;
  const quad dn = px * p.dx + py * p.dy;
  return dn * (ha + hb) - n * (dha + dhb);
}

struct UnitTable {
  std::array<long double, kSamples> cos_phi;
  std::array<long double, kSamples> sin_phi;
};

const UnitTable& unitTable() {
  static const UnitTable table = [] {
    UnitTable t{};
    const long double two_pi = 2.0L * std::acos(-1.0L);
    for (int k = 0; k < kSamples; ++k) {
      const long double phi = two_pi * k / kSamples;
      t.cos_phi[k] = std::cos(phi);
      t.sin_phi[k] = std::sin(phi);
    }
    return t;
  }();
  return table;
}

/// Index of the grid direction with the largest ratio, evaluated in long double.
int bestSample(const Problem& p) {
  using ld = long double;
  const Axes<ld> axes_a = narrow<ld>(p.a);
  const Axes<ld> axes_b = narrow<ld>(p.b);
  const ld dx = static_cast<ld>(p.dx), dy = static_cast<ld>(p.dy);
  const UnitTable& t = unitTable();
  int best = -1;
  ld best_ratio = 0.0L;
  for (int k = 0; k < kSamples; ++k) {
    const ld c = t.cos_phi[k], s = t.sin_phi[k];
    const ld n = c * dx + s * dy;
    if (n <= 0.0L) continue;  // the maximum is positive, so these can never win
    const ld ratio =
        n / (std::sqrt(axes_a.supportSquared(c, s)) + std::sqrt(axes_b.supportSquared(c, s)));
    if (best < 0 || ratio > best_ratio) {
      best = k;
      best_ratio = ratio;
    }
  }
  if (best < 0) throw std::logic_error("contact scale oracle: no direction with u . d > 0");
  return best;
}

}  // namespace

OracleContactScale oracleContactScale(const Ellipse& a, const Ellipse& b) {
  Problem p{quadAxes(a), quadAxes(b),
            static_cast<quad>(b.center.x()) - static_cast<quad>(a.center.x()),
            static_cast<quad>(b.center.y()) - static_cast<quad>(a.center.y())};
  OracleContactScale result;
  if (p.dx == 0 && p.dy == 0) return result;

  const int best = bestSample(p);
  const quad step = 2 * kQuadPi / kSamples;
  quad lo = step * (best - kBracketSamples);
  quad hi = step * (best + kBracketSamples);

  // The ratio rises to the left of the peak and falls to its right, so the slope's sign locates it.
  // A bracket without that sign change would make the oracle quietly wrong: refuse it instead.
  if (slopeNumeratorAt(p, lo) < 0 || slopeNumeratorAt(p, hi) > 0) {
    throw std::logic_error("contact scale oracle: the sampled bracket misses the maximum");
  }
  for (int i = 0; i < kMaxBisections && hi - lo > kPhiTolerance; ++i) {
    const quad mid = (lo + hi) / 2;
    if (slopeNumeratorAt(p, mid) > 0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }

  // Every evaluated ratio is a lower bound on t*, so keep the largest (guards a bad bracket).
  const quad candidates[] = {(lo + hi) / 2, lo, hi, step * best};
  result.phi = candidates[0];
  result.quad = ratioAt(p, candidates[0]);
  for (const quad phi : candidates) {
    const quad ratio = ratioAt(p, phi);
    if (ratio > result.quad) {
      result.quad = ratio;
      result.phi = phi;
    }
  }
  result.value = static_cast<double>(result.quad);
  return result;
}

bool oracleOverlap(const Ellipse& a, const Ellipse& b) {
  return oracleContactScale(a, b).quad <= 1;
}

Ellipse placeAtContactScale(const Ellipse& a, const Ellipse& b, double target) {
  if (!(target > 0.0)) throw std::invalid_argument("placeAtContactScale: target must be > 0");
  const quad t = oracleContactScale(a, b).quad;
  if (t == 0) throw std::invalid_argument("placeAtContactScale: the centres coincide");
  const quad factor = static_cast<quad>(target) / t;
  const quad ax = a.center.x(), ay = a.center.y();
  const quad dx = static_cast<quad>(b.center.x()) - ax;
  const quad dy = static_cast<quad>(b.center.y()) - ay;
  Ellipse moved = b;
  moved.center =
      Eigen::Vector2d(static_cast<double>(ax + dx * factor), static_cast<double>(ay + dy * factor));
  return moved;
}

std::string toString(__float128 value) {
  char buffer[64];
  quadmath_snprintf(buffer, sizeof buffer, "%.36Qg", value);
  return buffer;
}

std::string describePair(const Ellipse& a, const Ellipse& b) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer,
                "a = {%.17g, %.17g, %.17g, %.17g, %.17g}, b = {%.17g, %.17g, %.17g, %.17g, %.17g}",
                a.center.x(), a.center.y(), a.radius_x, a.radius_y, a.angle, b.center.x(),
                b.center.y(), b.radius_x, b.radius_y, b.angle);
  return buffer;
}

}  // namespace test
}  // namespace ellipse_collision::core
