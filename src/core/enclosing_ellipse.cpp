#include "ellipse_collision/core/enclosing_ellipse.h"

#include <Eigen/LU>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

#include "ellipse_collision/core/number_format.h"
#include "khachiyan_weights.h"
#include "rounded_up.h"

namespace ellipse_collision::core {
namespace {

using detail::roundedUp;
using detail::PointOrder;
using detail::weightedMoments;
using WeightSolver = detail::KhachiyanWeights<2>;

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

constexpr double kPi = 3.14159265358979323846;

// The first pass only has to find a frame in which the ellipse is round; the second pass, in that
// frame, goes down to kEnclosingGapTolerance.
constexpr double kCoarseGap = 1e-3;

// Rounds of the certification; each one grows the radii past the worst point, so one suffices
// unless rounding conspires.
constexpr int kCertificationRounds = 8;

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

bool lexicographicLess(const Vec2& a, const Vec2& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

/// Strictly convex hull, counter-clockwise, without duplicates or collinear points; the two ends
/// for collinear input, the point itself for one distinct point. Andrew's monotone chain,
/// O(n log n).
std::vector<Vec2> convexHull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), lexicographicLess);
  p.erase(std::unique(p.begin(), p.end(),
                      [](const Vec2& a, const Vec2& b) { return a.x() == b.x() && a.y() == b.y(); }),
          p.end());
  if (p.size() < 3) return p;
  std::vector<Vec2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i > 0; --i) {  // upper chain
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0.0) --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);  // the last point repeats the first
  return hull;
}

/// Smallest extent of a convex polygon (counter-clockwise, >= 3 vertices) over all directions,
/// by rotating calipers: the antipodal vertex of each edge only moves forward. O(n).
double hullWidth(const std::vector<Vec2>& hull) {
  const std::size_t n = hull.size();
  double width = std::numeric_limits<double>::infinity();
  std::size_t j = 1;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = hull[i];
    const Vec2& b = hull[(i + 1) % n];
    const double length = (b - a).norm();
    if (!(length > 0.0)) continue;
    // Bounded by n steps so that rounding can never make it circle.
    for (std::size_t step = 0; step < n && cross(a, b, hull[(j + 1) % n]) > cross(a, b, hull[j]);
         ++step) {
      j = (j + 1) % n;
    }
    width = std::min(width, cross(a, b, hull[j]) / length);
  }
  return width;
}

/// An affine map x -> origin + linear * x, composed as the frames below are nested.
struct Affine {
  Vec2 origin{0.0, 0.0};
  Mat2 linear{Mat2::Identity()};
  double det{1.0};  ///< det(linear), kept as a product of well-conditioned factors

  Vec2 apply(const Vec2& x) const { return origin + linear * x; }
  /// this o inner.
  Affine then(const Affine& inner) const {
    return {apply(inner.origin), linear * inner.linear, det * inner.det};
  }
};

/// Lower-triangular L with L L^T = s (s symmetric positive definite).
Mat2 cholesky(const Mat2& s) {
  const double l00 = std::sqrt(s(0, 0));
  const double l10 = s(1, 0) / l00;
  const double l11 = std::sqrt(std::max(s(1, 1) - l10 * l10, 0.0));
  Mat2 l;
  l << l00, 0.0, l10, l11;
  return l;
}

/// The frame in which the weighted points have centre 0 and covariance I: z -> c + L w.
Affine whiteningFrame(const std::vector<Vec2>& points, const std::vector<double>& u) {
  const auto [c, s] = weightedMoments(points, u);
  const Mat2 l = cholesky(s);
  return {c, l, l(0, 0) * l(1, 1)};
}

std::vector<Vec2> intoFrame(const Affine& frame, const std::vector<Vec2>& points) {
  const Mat2 inverse = frame.linear.inverse();
  std::vector<Vec2> out;
  out.reserve(points.size());
  for (const Vec2& p : points) out.push_back(inverse * (p - frame.origin));
  return out;
}

/// The frame of the points' principal axes, scaled to their extents along them: z -> origin +
/// R(phi) diag(ex, ey) z. Makes thin sets round enough for the first pass.
Affine principalFrame(const std::vector<Vec2>& points) {
  Vec2 mean = Vec2::Zero();
  for (const Vec2& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Mat2 s = Mat2::Zero();
  for (const Vec2& p : points) s.noalias() += (p - mean) * (p - mean).transpose();
  const double phi = 0.5 * std::atan2(2.0 * s(0, 1), s(0, 0) - s(1, 1));
  const double c = std::cos(phi), sn = std::sin(phi);
  double ex = 0.0, ey = 0.0;
  for (const Vec2& p : points) {
    const Vec2 d = p - mean;
    ex = std::max(ex, std::abs(c * d.x() + sn * d.y()));
    ey = std::max(ey, std::abs(-sn * d.x() + c * d.y()));
  }
  Mat2 linear;
  linear << c * ex, -sn * ey, sn * ex, c * ey;
  return {mean, linear, ex * ey};
}

/// Initial core set: the extreme points along eight directions, and the point farthest from the
/// line through the first two, so that the moment matrix is invertible.
void seedCore(const std::vector<Vec2>& points, WeightSolver& solver) {
  std::vector<std::size_t> chosen;
  for (int k = 0; k < 8; ++k) {
    const Vec2 direction{std::cos(k * kPi / 4.0), std::sin(k * kPi / 4.0)};
    std::size_t best = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
      if (points[i].dot(direction) > points[best].dot(direction)) best = i;
    }
    chosen.push_back(best);
  }
  const Vec2 a = points[chosen[0]], b = points[chosen[4]];
  std::size_t far = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (std::abs(cross(a, b, points[i])) > std::abs(cross(a, b, points[far]))) far = i;
  }
  chosen.push_back(far);
  for (const std::size_t i : chosen) solver.addToCore(i);
  solver.spreadUniformlyOverCore();
}

/// Radii and angle of {centre + m y : |y| <= 1}, given det(m) as an accurate product: the major
/// radius from the largest eigenvalue of m m^T, the minor one as |det| / major (no cancellation
/// for thin ellipses), the angle from the eigenvector.
Ellipse ellipseFromMap(const Vec2& centre, const Mat2& m, double det) {
  const Mat2 s = m * m.transpose();
  const double half_sum = 0.5 * (s(0, 0) + s(1, 1));
  const double half_diff = 0.5 * (s(0, 0) - s(1, 1));
  const double major = std::sqrt(half_sum + std::hypot(half_diff, s(0, 1)));
  Ellipse e;
  e.center = centre;
  e.radius_x = major;
  e.radius_y = std::abs(det) / major;
  double angle = 0.5 * std::atan2(s(0, 1), half_diff);
  if (angle <= -0.5 * kPi) angle += kPi;  // keep (-pi/2, pi/2]
  e.angle = angle;
  return e;
}

/// The largest normalised quadratic form ((p - c) in the ellipse's axes, divided by the radii,
/// squared and summed) over the points, in long double.
long double largestQuadraticForm(const Ellipse& e, const std::vector<Vec2>& points) {
  const long double c = std::cos(static_cast<long double>(e.angle));
  const long double s = std::sin(static_cast<long double>(e.angle));
  const long double rx = e.radius_x, ry = e.radius_y;
  long double worst = 0.0L;
  for (const Vec2& p : points) {
    const long double dx = static_cast<long double>(p.x()) - e.center.x();
    const long double dy = static_cast<long double>(p.y()) - e.center.y();
    const long double along = (c * dx + s * dy) / rx;
    const long double across = (c * dy - s * dx) / ry;
    worst = std::max(worst, along * along + across * across);
  }
  return worst;
}

/// Grows both radii by the smallest factor (plus a few ulps) that puts every point inside, as
/// evaluated from the double fields: the long double evaluation's rounding (at most a few
/// long double epsilons times the axis ratio, from the cancellation in the rotation) is kept as a
/// margin below 1. Returns false if that did not succeed (a non-finite radius).
bool certify(Ellipse& e, const std::vector<Vec2>& points) {
  const long double eps = std::numeric_limits<long double>::epsilon();
  for (int round = 0; round < kCertificationRounds; ++round) {
    if (!std::isfinite(e.radius_x) || !std::isfinite(e.radius_y)) return false;
    const long double ratio = std::max(e.radius_x / e.radius_y, e.radius_y / e.radius_x);
    const long double limit = 1.0L - 64.0L * eps * (1.0L + ratio);
    const long double worst = largestQuadraticForm(e, points);
    if (worst <= limit) return true;
    const long double factor = std::sqrt(worst / limit) * (1.0L + 4.0L * DBL_EPSILON);
    e.radius_x = roundedUp(e.radius_x * factor);
    e.radius_y = roundedUp(e.radius_y * factor);
  }
  return false;
}

std::string validationError(const std::vector<Vec2>& points) {
  if (points.empty()) return "points is empty";
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      if (auto violation = coordinateViolation(points[i][axis])) {
        const std::string head = "points[" + std::to_string(i) + "]." + (axis == 0 ? "x" : "y") +
                                 " = " + formatNumber(violation->value);
        if (violation->rule == ValueViolation::Rule::Finite) return head + " is not finite";
        return head + " is outside [" + formatNumber(violation->min) + ", " +
               formatNumber(violation->max) + "] m";
      }
    }
  }
  return {};
}

EnclosingEllipse errorResult(std::string message) {
  EnclosingEllipse result;
  result.status = EnclosingStatus::Error;
  result.error = std::move(message);
  return result;
}

/// The Degenerate description: the segment between the extreme projections on the direction
/// from the lexicographically first to the last point (the ends of a collinear set), and the
/// largest distance from that line.
EnclosingEllipse degenerateResult(const std::vector<Vec2>& points) {
  const auto [first, last] = std::minmax_element(points.begin(), points.end(), lexicographicLess);
  const Vec2 a = *first;
  Vec2 direction = *last - a;
  const double length = direction.norm();
  direction = length > 0.0 ? Vec2(direction / length) : Vec2(1.0, 0.0);
  const long double ux = direction.x(), uy = direction.y();
  long double lo = 0.0L, hi = 0.0L, width = 0.0L, extent = 0.0L;
  for (const Vec2& p : points) {
    const long double dx = static_cast<long double>(p.x()) - a.x();
    const long double dy = static_cast<long double>(p.y()) - a.y();
    const long double along = ux * dx + uy * dy;
    lo = std::min(lo, along);
    hi = std::max(hi, along);
    width = std::max(width, std::abs(ux * dy - uy * dx));
    extent = std::max(extent, std::abs(dx) + std::abs(dy));
  }
  EnclosingEllipse result;
  result.status = EnclosingStatus::Degenerate;
  result.segment_start = a + static_cast<double>(lo) * direction;
  result.segment_end = a + static_cast<double>(hi) * direction;
  // The rounding of the ends and of the unit direction, a few ulps of the extent.
  result.half_width = roundedUp(width + 8.0L * DBL_EPSILON * extent);
  return result;
}

/// The band of `points` along the unit `direction`: the segment between the extreme projections,
/// on the line through the middle of the band, and the band's half-width (rounded up, with the
/// rounding of the ends, as degenerateResult()).
EnclosingEllipse bandAlong(const std::vector<Vec2>& points, const Vec2& direction) {
  const Vec2 a = points.front();
  const long double ux = direction.x(), uy = direction.y();
  long double lo = 0.0L, hi = 0.0L, across_lo = 0.0L, across_hi = 0.0L, extent = 0.0L;
  for (const Vec2& p : points) {
    const long double dx = static_cast<long double>(p.x()) - a.x();
    const long double dy = static_cast<long double>(p.y()) - a.y();
    const long double along = ux * dx + uy * dy, across = ux * dy - uy * dx;
    lo = std::min(lo, along);
    hi = std::max(hi, along);
    across_lo = std::min(across_lo, across);
    across_hi = std::max(across_hi, across);
    extent = std::max(extent, std::abs(dx) + std::abs(dy));
  }
  const long double middle = 0.5L * (across_lo + across_hi);
  const Vec2 normal(-direction.y(), direction.x());
  EnclosingEllipse result;
  result.status = EnclosingStatus::Degenerate;
  result.segment_start = a + static_cast<double>(lo) * direction + static_cast<double>(middle) * normal;
  result.segment_end = a + static_cast<double>(hi) * direction + static_cast<double>(middle) * normal;
  result.half_width = roundedUp(0.5L * (across_hi - across_lo) + 8.0L * DBL_EPSILON * extent);
  return result;
}

/// The ellipse around a Degenerate description's segment and half-width with both radii >=
/// min_radius: the box of half-sizes (h, w) around the segment lies in the ellipse of radii
/// (a, b) when h^2 / a^2 + w^2 / b^2 <= 1; b >= sqrt(2) w keeps a <= sqrt(2) h. Not certified.
Ellipse segmentEllipse(const EnclosingEllipse& segment, double min_radius) {
  const Vec2 along = segment.segment_end - segment.segment_start;
  const double half_length = 0.5 * along.norm();
  const double w = segment.half_width;
  const double b = std::max(min_radius, std::sqrt(2.0) * w);
  const double a = std::max(min_radius, half_length / std::sqrt(1.0 - (w / b) * (w / b)));
  Ellipse e;
  e.center = 0.5 * (segment.segment_start + segment.segment_end);
  e.angle = half_length > 0.0 ? std::atan2(along.y(), along.x()) : 0.0;
  if (e.angle > 0.5 * kPi) e.angle -= kPi;
  if (e.angle <= -0.5 * kPi) e.angle += kPi;
  e.radius_x = a;
  e.radius_y = b;
  if (b > a) {
    std::swap(e.radius_x, e.radius_y);
    e.angle += e.angle > 0.0 ? -0.5 * kPi : 0.5 * kPi;
  }
  return e;
}

std::string outOfRange(const Ellipse& e) {
  const std::string reason = invalidReason(e);
  return reason.empty() ? reason : "the enclosing ellipse is out of range: " + reason;
}

/// Why `min_radius` is refused, or nothing.
std::optional<std::string> minRadiusError(double min_radius) {
  const auto violation = radiusViolation(min_radius);
  if (!violation) return std::nullopt;
  const std::string head = "min_radius = " + formatNumber(min_radius);
  if (violation->rule == ValueViolation::Rule::Finite) return head + " is not finite";
  if (violation->rule == ValueViolation::Rule::Positive) return head + " must be > 0";
  return head + " is outside [" + formatNumber(violation->min) + ", " +
         formatNumber(violation->max) + "] m";
}

/// The Ok result for `e` once certified and within range, else the Error.
EnclosingEllipse certifiedResult(Ellipse e, const std::vector<Vec2>& points) {
  if (!certify(e, points)) {
    return errorResult("the enclosing ellipse could not be certified (radius_x = " +
                       formatNumber(e.radius_x) + ")");
  }
  if (std::string error = outOfRange(e); !error.empty()) return errorResult(error);
  EnclosingEllipse result;
  result.status = EnclosingStatus::Ok;
  result.ellipse = e;
  return result;
}

}  // namespace

EnclosingEllipse minimumAreaEllipse(const std::vector<Eigen::Vector2d>& points) {
  if (std::string error = validationError(points); !error.empty()) return errorResult(error);

  // Unit frame: the bounding box's centre and half-extent, so that 1e6 offsets and 1e-4 sizes
  // look alike to the optimiser.
  Vec2 low = points.front(), high = points.front();
  for (const Vec2& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  Affine unit;
  unit.origin = 0.5 * (low + high);
  const double scale = 0.5 * (high - low).maxCoeff();
  if (!(scale > 0.0)) return degenerateResult(points);
  unit.linear = scale * Mat2::Identity();
  unit.det = scale * scale;

  const std::vector<Vec2> hull = convexHull(intoFrame(unit, points));
  if (hull.size() < 3) return degenerateResult(points);
  const double width = hullWidth(hull);  // in units of `scale`; the extent is 2 to 2.8
  if (width <= 2.0 * kDegenerateRelativeWidth || width * scale < 2.0 * kMinRadius) {
    return degenerateResult(points);
  }

  // First pass in the principal-axes frame, second in the frame where the first estimate is
  // round. The weights are affine-invariant, so the second pass continues from the first.
  const Affine principal = principalFrame(hull);
  const std::vector<Vec2> z = intoFrame(principal, hull);
  WeightSolver solver(hull.size(), PointOrder::ConvexPolygon, kMaxOptimiserIterations);
  seedCore(z, solver);
  solver.solve(z, kCoarseGap);
  const Affine round = whiteningFrame(z, solver.weights());
  const std::vector<Vec2> w = intoFrame(round, z);
  const double gap = solver.solve(w, kEnclosingGapTolerance);

  // The ellipse {c + sqrt(r) L y}, L L^T the weighted covariance, r the largest Mahalanobis
  // radius over the hull: it contains every hull point by construction.
  const auto [centre, covariance] = weightedMoments(w, solver.weights());
  const Mat2 inverse = covariance.inverse();
  double reach = 0.0;
  for (const Vec2& p : w) reach = std::max(reach, (p - centre).dot(inverse * (p - centre)));
  const Mat2 l = cholesky(covariance);
  const double root = std::sqrt(reach);
  const Affine fitted{centre, root * l, reach * l(0, 0) * l(1, 1)};

  const Affine total = unit.then(principal).then(round).then(fitted);
  EnclosingEllipse result;
  result.status = EnclosingStatus::Ok;
  result.ellipse = ellipseFromMap(total.origin, total.linear, total.det);
  // area = pi sqrt(det S) reach with det S <= det S* (dual optimality) and reach <= 2 + 3 gap.
  result.area_excess_bound = std::max(0.0, 1.5 * gap);
  const double excess = result.area_excess_bound;
  EnclosingEllipse certified = certifiedResult(result.ellipse, points);
  if (certified.ok()) certified.area_excess_bound = excess;
  return certified;
}

EnclosingEllipse bandEllipse(const std::vector<Eigen::Vector2d>& points,
                             const Eigen::Vector2d& direction, double min_radius) {
  if (auto error = minRadiusError(min_radius)) return errorResult(*error);
  if (std::string error = validationError(points); !error.empty()) return errorResult(error);
  return certifiedResult(segmentEllipse(bandAlong(points, direction), min_radius), points);
}

EnclosingEllipse enclosingEllipseWithMinRadius(const std::vector<Eigen::Vector2d>& points,
                                               double min_radius) {
  if (auto error = minRadiusError(min_radius)) return errorResult(*error);
  EnclosingEllipse result = minimumAreaEllipse(points);
  if (result.status == EnclosingStatus::Error) return result;
  if (result.status == EnclosingStatus::Ok) {
    const Ellipse minimum = result.ellipse;
    // A larger radius on the same axes gives an ellipse containing the old one.
    result.ellipse.radius_x = std::max(result.ellipse.radius_x, min_radius);
    result.ellipse.radius_y = std::max(result.ellipse.radius_y, min_radius);
    if (result.ellipse.radius_y > result.ellipse.radius_x) {
      std::swap(result.ellipse.radius_x, result.ellipse.radius_y);
      result.ellipse.angle += result.ellipse.angle > 0.0 ? -0.5 * kPi : 0.5 * kPi;
    }
    if (minimum.radius_y < min_radius) {
      // A thin set (a noisy wall): the minimum-area ellipse of a thin band is sqrt(2) times
      // longer than the band, and raising its minor radius keeps that length. The band's own
      // ellipse (as for collinear sets) along the major axis is then often much smaller.
      const Vec2 direction(std::cos(minimum.angle), std::sin(minimum.angle));
      Ellipse band = segmentEllipse(bandAlong(points, direction), min_radius);
      if (certify(band, points) &&
          band.radius_x * band.radius_y < result.ellipse.radius_x * result.ellipse.radius_y) {
        result.ellipse = band;
      }
    }
  } else {
    const Ellipse e = segmentEllipse(result, min_radius);
    result = EnclosingEllipse{};
    result.status = EnclosingStatus::Ok;
    result.ellipse = e;
  }
  const double excess = result.area_excess_bound;
  EnclosingEllipse certified = certifiedResult(result.ellipse, points);
  if (certified.ok()) certified.area_excess_bound = excess;
  return certified;
}

}  // namespace ellipse_collision::core
