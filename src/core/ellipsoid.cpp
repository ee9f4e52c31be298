#include "ellipse_collision/core/ellipsoid.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "ellipse_collision/core/number_format.h"
#include "ellipsoid_detail.h"

namespace ellipse_collision::core {
namespace {

using detail::LongMat3;
using LD = long double;

// The quaternion may be off unit norm by this much (YAML with a few decimals, tf's float
// rounding); the rotation is that of the normalised quaternion either way.
constexpr double kUnitQuaternionTolerance = 1e-6;

}  // namespace

namespace detail {

LongMat3 rotationOf(const Eigen::Quaterniond& orientation) {
  LD w = orientation.w(), x = orientation.x(), y = orientation.y(), z = orientation.z();
  const LD norm = std::sqrt(w * w + x * x + y * y + z * z);
  w /= norm, x /= norm, y /= norm, z /= norm;
  LongMat3 r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return r;
}

}  // namespace detail

std::string invalidReason(const Ellipsoid& ellipsoid) {
  const char* const axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (auto violation = coordinateViolation(ellipsoid.center[i])) {
      return renderViolation(("center." + std::string(axes[i])).c_str(), *violation);
    }
  }
  for (int i = 0; i < 3; ++i) {
    if (auto violation = radiusViolation(ellipsoid.radii[i])) {
      return renderViolation(("radii." + std::string(axes[i])).c_str(), *violation);
    }
  }
  const Eigen::Vector4d q = ellipsoid.orientation.coeffs();
  if (!q.allFinite()) return "orientation has a component that is not finite";
  if (!(std::abs(q.norm() - 1.0) <= kUnitQuaternionTolerance)) {
    return "orientation is not a unit quaternion (norm " + formatNumber(q.norm()) + ")";
  }
  return {};
}

Eigen::Matrix3d shapeMatrix(const Ellipsoid& ellipsoid) {
  const LongMat3 m = detail::rotationOf(ellipsoid.orientation) *
                     ellipsoid.radii.cast<LD>().asDiagonal();
  return (m * m.transpose()).cast<double>();
}

ProjectionResult shadowOnPlane(const Ellipsoid& in_frame, const Eigen::Isometry3d& fixed_from_frame,
                               const std::string& name) {
  ProjectionResult result;
  if (const std::string invalid = invalidReason(in_frame); !invalid.empty()) {
    result.error = "ellipsoid '" + name + "': " + invalid;
    return result;
  }
  if (!fixed_from_frame.matrix().allFinite()) {
    result.error = "ellipsoid '" + name + "': the transform of its frame is not finite";
    return result;
  }
  const LongMat3 p = fixed_from_frame.linear().cast<LD>();
  // M = P Q diag(r): the placed ellipsoid is {c' + M u : |u| <= 1}; its shadow {c'.xy + M_xy u}.
  const LongMat3 m = p * detail::rotationOf(in_frame.orientation) * in_frame.radii.cast<LD>().asDiagonal();
  const Eigen::Matrix<LD, 3, 1> centre =
      p * in_frame.center.cast<LD>() + fixed_from_frame.translation().cast<LD>();
  const LD s00 = m.row(0).squaredNorm(), s11 = m.row(1).squaredNorm(), s01 = m.row(0).dot(m.row(1));
  // det S by Cauchy–Binet: the sum of the squared 2x2 minors of M_xy, each a product of radii
  // times a cofactor of the rotation, so a thin shadow's determinant keeps its relative precision.
  LD det = 0.0L;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const LD minor = m(0, i) * m(1, j) - m(0, j) * m(1, i);
    det += minor * minor;
  }
  const LD half_sum = 0.5L * (s00 + s11), half_diff = 0.5L * (s00 - s11);
  const LD major_squared = half_sum + std::hypot(half_diff, s01);
  const LD major = std::sqrt(major_squared);
  const LD minor = std::sqrt(det) / major;

  Ellipse& e = result.ellipse;
  e.center = centre.head<2>().cast<double>();
  e.angle = static_cast<double>(0.5L * std::atan2(2.0L * s01, s00 - s11));  // in (-pi/2, pi/2]
  e.radius_x = detail::roundedUp(major);
  e.radius_y = detail::roundedUp(minor);

  // Certification: the rounded ellipse E' (shape S' = R' D' R'^T) must contain the shadow
  // (shape S = M_xy M_xy^T, centre c'). Same centre: S <= S' iff the largest eigenvalue of
  // T = N N^T, N = D'^-1/2 R'^T M_xy, is <= 1; the radii grow by its square root. The centre's
  // rounding d is then covered by scaling both radii by 1 + d / b (the disk of radius d lies in
  // (d / b) E', so E' + that disk lies in (1 + d / b) E').
  const LD eps = std::numeric_limits<LD>::epsilon();
  const LD c = std::cos(static_cast<LD>(e.angle)), s = std::sin(static_cast<LD>(e.angle));
  const LD a = e.radius_x, b = e.radius_y;
  const Eigen::Matrix<LD, 1, 3> n0 = (c * m.row(0) + s * m.row(1)) / a;
  const Eigen::Matrix<LD, 1, 3> n1 = (c * m.row(1) - s * m.row(0)) / b;
  const LD t00 = n0.squaredNorm(), t11 = n1.squaredNorm(), t01 = n0.dot(n1);
  const LD largest = 0.5L * (t00 + t11) + std::hypot(0.5L * (t00 - t11), t01);
  // n1 cancels: its error is a few eps times the axis ratio (relative to its norm, about 1).
  const LD ratio = a / b;
  const LD limit = 1.0L - 64.0L * eps * (1.0L + ratio);
  // The bound is only of use while small against 1: past an axis ratio of about 7e16 (a needle
  // at least 7e7 m long, as kMinRadius bounds its width) the thin side is lost in that error, and
  // the limit would reach 0 (and the growth NaN at a ratio of 1.4e17). Refused, not guessed.
  if (!(limit >= 0.5L)) {
    result.error = "ellipsoid '" + name + "': its shadow is too thin to certify (axis ratio " +
                   formatNumber(static_cast<double>(ratio)) + ", at most " +
                   formatNumber(static_cast<double>(0.5L / (64.0L * eps) - 1.0L)) + ")";
    return result;
  }
  const LD growth = largest > limit ? std::sqrt(largest / limit) : 1.0L;
  const LD drift = std::hypot(centre.x() - static_cast<LD>(e.center.x()),
                              centre.y() - static_cast<LD>(e.center.y())) +
                   16.0L * eps *
                       (fixed_from_frame.translation().cast<LD>().cwiseAbs().sum() +
                        in_frame.center.cast<LD>().cwiseAbs().sum());
  const LD pad = 1.0L + 4.0L * DBL_EPSILON;
  const LD scaling = growth * (1.0L + drift / (b * growth)) * pad;
  e.radius_x = detail::roundedUp(a * scaling);
  e.radius_y = detail::roundedUp(b * scaling);

  if (const std::string unusable = invalidReason(e); !unusable.empty()) {
    result.error = "ellipsoid '" + name + "': its shadow is out of range (" + unusable + ")";
  }
  return result;
}

}  // namespace ellipse_collision::core
