#include "enclosing_ellipse_oracle.h"

#include <quadmath.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <type_traits>
#include <utility>
#include <vector>

namespace ellipse_collision::core {
namespace test {
namespace {

using quad = __float128;

// Parameters: B = [[t0, t1], [t1, t2]], b = (t3, t4).
constexpr int kParameters = 5;
using Vector = std::array<quad, kParameters>;
using Matrix = std::array<Vector, kParameters>;

constexpr int kMaxNewtonSteps = 500;
constexpr int kMaxHalvings = 200;
// Each stage divides the barrier weight by this.
constexpr double kMuFactor = 0.05;
// Cutting planes: initial sample size, points added per round, rounds, and the subset size up to
// which the quad solver is used.
constexpr std::size_t kCuttingPlaneStart = 64;
constexpr std::size_t kCuttingPlaneAdditions = 32;
constexpr int kCuttingPlaneRounds = 40;
constexpr std::size_t kQuadCuttingPlaneMax = 0;

template <typename T>
T sqrtOf(T x) {
  if constexpr (std::is_same_v<T, quad>) {
    return sqrtq(x);
  } else {
    return std::sqrt(x);
  }
}
template <typename T>
T logOf(T x) {
  if constexpr (std::is_same_v<T, quad>) {
    return logq(x);
  } else {
    return std::log(x);
  }
}

/// The barrier problem in arithmetic T on points already centred and scaled to unit size.
template <typename T>
class Barrier {
 public:
  explicit Barrier(std::vector<std::array<T, 2>> points) : points_(std::move(points)) {}

  /// f = -log det B - mu sum log(1 - |B p + b|^2); false when theta is infeasible.
  bool value(const std::array<T, kParameters>& t, T mu, T& f) const {
    const T det = t[0] * t[2] - t[1] * t[1];
    if (!(t[0] > 0) || !(det > 0)) return false;
    T sum = 0;
    for (const auto& p : points_) {
      const T y0 = t[0] * p[0] + t[1] * p[1] + t[3];
      const T y1 = t[1] * p[0] + t[2] * p[1] + t[4];
      const T g = 1 - y0 * y0 - y1 * y1;
      if (!(g > 0)) return false;
      sum += logOf(g);
    }
    f = -logOf(det) - mu * sum;
    return true;
  }

  /// One Newton step's direction; returns the squared Newton decrement.
  T newtonDirection(const std::array<T, kParameters>& t, T mu,
                    std::array<T, kParameters>& direction) const {
    std::array<std::array<T, kParameters>, kParameters> h{};
    std::array<T, kParameters> grad{};
    const T det = t[0] * t[2] - t[1] * t[1];
    const std::array<T, 3> ddet = {t[2], -2 * t[1], t[0]};
    for (int i = 0; i < 3; ++i) {
      grad[i] = -ddet[i] / det;
      for (int j = 0; j < 3; ++j) h[i][j] = ddet[i] * ddet[j] / (det * det);
    }
    h[0][2] -= 1 / det;
    h[2][0] -= 1 / det;
    h[1][1] += 2 / det;
    for (const auto& p : points_) {
      const T y0 = t[0] * p[0] + t[1] * p[1] + t[3];
      const T y1 = t[1] * p[0] + t[2] * p[1] + t[4];
      const T g = 1 - y0 * y0 - y1 * y1;
      // Rows of J = dy / dtheta.
      const std::array<T, kParameters> j0 = {p[0], p[1], 0, 1, 0};
      const std::array<T, kParameters> j1 = {0, p[0], p[1], 0, 1};
      std::array<T, kParameters> jy;
      for (int i = 0; i < kParameters; ++i) jy[i] = j0[i] * y0 + j1[i] * y1;
      const T a = 2 * mu / g, c = 4 * mu / (g * g);
      for (int i = 0; i < kParameters; ++i) {
        grad[i] += a * jy[i];
        for (int k = 0; k < kParameters; ++k) {
          h[i][k] += c * jy[i] * jy[k] + a * (j0[i] * j0[k] + j1[i] * j1[k]);
        }
      }
    }
    // Solve h d = -grad by Cholesky (h is positive definite).
    std::array<std::array<T, kParameters>, kParameters> l{};
    for (int i = 0; i < kParameters; ++i) {
      for (int k = 0; k <= i; ++k) {
        T s = h[i][k];
        for (int m = 0; m < k; ++m) s -= l[i][m] * l[k][m];
        l[i][k] = i == k ? sqrtOf(s) : s / l[k][k];
      }
    }
    std::array<T, kParameters> z{};
    for (int i = 0; i < kParameters; ++i) {
      T s = -grad[i];
      for (int m = 0; m < i; ++m) s -= l[i][m] * z[m];
      z[i] = s / l[i][i];
    }
    for (int i = kParameters - 1; i >= 0; --i) {
      T s = z[i];
      for (int m = i + 1; m < kParameters; ++m) s -= l[m][i] * direction[m];
      direction[i] = s / l[i][i];
    }
    T decrement = 0;
    for (int i = 0; i < kParameters; ++i) decrement -= grad[i] * direction[i];
    return decrement;
  }

  /// Minimises the barrier problem for each mu down to target / n; returns whether the last
  /// stage converged (its scaled Newton decrement fell below 1e-4, or 0.1 at the rounding floor) and the final mu.
  bool solve(std::array<T, kParameters>& t, T target, T& final_mu) const {
    const T n = static_cast<T>(points_.size());
        bool converged = false;
    for (T mu = 1;; mu *= static_cast<T>(kMuFactor)) {
      bool stage_converged = false;
      for (int step = 0; step < kMaxNewtonSteps; ++step) {
        std::array<T, kParameters> d;
        const T decrement = newtonDirection(t, mu, d);
        if (!(decrement == decrement)) break;  // NaN: the Hessian lost definiteness to rounding
        // The decrement of the self-concordant f / mu: below 1e-4 the centring error (about
        // mu times it) is far below the stage's gap bound n mu.
        if (!(decrement > static_cast<T>(1e-4) * mu)) {
          stage_converged = true;
          break;
        }
        T f0 = 0;
        value(t, mu, f0);
        T alpha = 1;
        bool accepted = false;
        for (int halving = 0; halving < kMaxHalvings; ++halving, alpha /= 2) {
          std::array<T, kParameters> trial;
          for (int i = 0; i < kParameters; ++i) trial[i] = t[i] + alpha * d[i];
          T f1;
          if (value(trial, mu, f1) && f1 <= f0 - static_cast<T>(0.25) * alpha * decrement) {
            t = trial;
            accepted = true;
            break;
          }
        }
        if (!accepted) {
          stage_converged = decrement < static_cast<T>(0.1) * mu;  // rounding floor reached
          break;
        }
      }
      // Only the last stage's centring matters for the final bound.
      converged = stage_converged;
      final_mu = mu;
      if (mu * n <= target) break;
    }
    return converged;
  }

 private:
  std::vector<std::array<T, 2>> points_;
};

template <typename T>
OracleEllipse solveIn(const std::vector<Eigen::Vector2d>& points, T target) {
  // Centre on the mean and scale to unit size in quad, then narrow.
  quad mx = 0, my = 0;
  for (const auto& p : points) mx += p.x(), my += p.y();
  mx /= points.size();
  my /= points.size();
  quad scale = 0;
  for (const auto& p : points) {
    const quad dx = p.x() - mx, dy = p.y() - my;
    const quad r = sqrtq(dx * dx + dy * dy);
    if (r > scale) scale = r;
  }
  std::vector<std::array<T, 2>> unit;
  for (const auto& p : points) {
    unit.push_back({static_cast<T>((p.x() - mx) / scale), static_cast<T>((p.y() - my) / scale)});
  }
  Barrier<T> barrier(unit);
  std::array<T, kParameters> t = {static_cast<T>(0.5), 0, static_cast<T>(0.5), 0, 0};
  T mu = 0;
  OracleEllipse out;
  out.converged = barrier.solve(t, target, mu);
  const quad det = static_cast<quad>(t[0]) * static_cast<quad>(t[2]) -
                   static_cast<quad>(t[1]) * static_cast<quad>(t[1]);
  out.area = acosq(-1) * scale * scale / det;
  out.gap = static_cast<quad>(mu) * static_cast<quad>(points.size());
  // Centre: -B^-1 b.
  const quad b0 = t[3], b1 = t[4];
  out.center_x = mx + scale * (-(static_cast<quad>(t[2]) * b0 - static_cast<quad>(t[1]) * b1) / det);
  out.center_y = my + scale * (-(-static_cast<quad>(t[1]) * b0 + static_cast<quad>(t[0]) * b1) / det);
  // In the caller's coordinates: |B (p - m) / s + b| = |(B / s) p + (b - B m / s)|.
  out.b_xx = static_cast<quad>(t[0]) / scale;
  out.b_xy = static_cast<quad>(t[1]) / scale;
  out.b_yy = static_cast<quad>(t[2]) / scale;
  out.b_x = static_cast<quad>(t[3]) - (out.b_xx * mx + out.b_xy * my);
  out.b_y = static_cast<quad>(t[4]) - (out.b_xy * mx + out.b_yy * my);
  return out;
}

}  // namespace

OracleEllipse oracleMinimumAreaEllipse(const std::vector<Eigen::Vector2d>& points,
                                       OraclePrecision precision) {
  if (precision == OraclePrecision::Quad) return solveIn<quad>(points, static_cast<quad>(1e-24));
  return solveIn<long double>(points, 1e-12L);
}

__float128 oracleQuadraticForm(const OracleEllipse& e, const Eigen::Vector2d& p) {
  const quad y0 = e.b_xx * p.x() + e.b_xy * p.y() + e.b_x;
  const quad y1 = e.b_xy * p.x() + e.b_yy * p.y() + e.b_y;
  return y0 * y0 + y1 * y1;
}

OracleEllipse oracleMinimumAreaEllipseByCuttingPlanes(const std::vector<Eigen::Vector2d>& points) {
  // Start from a spread-out sample: every k-th point plus the extremes along 16 directions.
  const std::size_t stride = std::max<std::size_t>(1, points.size() / kCuttingPlaneStart);
  std::vector<char> chosen(points.size(), 0);
  for (std::size_t i = 0; i < points.size(); i += stride) chosen[i] = 1;
  for (int k = 0; k < 16; ++k) {
    const double phi = 2.0 * 3.14159265358979323846 * k / 16;
    std::size_t best = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
      if (points[i].x() * std::cos(phi) + points[i].y() * std::sin(phi) >
          points[best].x() * std::cos(phi) + points[best].y() * std::sin(phi)) {
        best = i;
      }
    }
    chosen[best] = 1;
  }
  OracleEllipse result;
  for (int round = 0; round < kCuttingPlaneRounds; ++round) {
    std::vector<Eigen::Vector2d> subset;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (chosen[i]) subset.push_back(points[i]);
    }
    result = oracleMinimumAreaEllipse(subset, subset.size() <= kQuadCuttingPlaneMax
                                                  ? OraclePrecision::Quad
                                                  : OraclePrecision::LongDouble);
    std::vector<std::pair<quad, std::size_t>> outside;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const quad q = oracleQuadraticForm(result, points[i]);
      if (!chosen[i] && q > 1) outside.emplace_back(q, i);
    }
    if (outside.empty()) return result;
    std::sort(outside.begin(), outside.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t k = 0; k < outside.size() && k < kCuttingPlaneAdditions; ++k) chosen[outside[k].second] = 1;
  }
  result.converged = false;
  return result;
}

__float128 quadQuadraticForm(const Ellipse& e, const Eigen::Vector2d& p) {
  quad s, c;
  sincosq(static_cast<quad>(e.angle), &s, &c);
  const quad dx = static_cast<quad>(p.x()) - e.center.x();
  const quad dy = static_cast<quad>(p.y()) - e.center.y();
  const quad along = (c * dx + s * dy) / e.radius_x;
  const quad across = (c * dy - s * dx) / e.radius_y;
  return along * along + across * across;
}

__float128 quadArea(const Ellipse& e) {
  return acosq(-1) * static_cast<quad>(e.radius_x) * static_cast<quad>(e.radius_y);
}

std::string describeEllipse(const Ellipse& e) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "{%.17g, %.17g, %.17g, %.17g, %.17g}", e.center.x(),
                e.center.y(), e.radius_x, e.radius_y, e.angle);
  return buffer;
}

}  // namespace test
}  // namespace ellipse_collision::core
