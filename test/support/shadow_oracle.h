#pragma once

// Independent reference for the shadow of an ellipsoid on the fixed frame's plane, in quad
// precision, shared by test_ellipsoid (core::shadowOnPlane()) and the app tests (links and
// obstacles placed by their shadow): the placed ellipsoid is {centre + map u : |u| <= 1}, so its
// surface points project to (centre + map u).xy and the point furthest along a direction w of the
// plane is u = map^T w / |map^T w| (Cauchy–Schwarz). A shadow is exact when every projected
// surface point lies in it and each support point on its rim. No solver is shared with the core:
// the oracle only evaluates the shadow's quadratic form at points of the ellipsoid.
// Header-only, like distance_oracle.h.

#include <quadmath.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/ellipsoid.h"
#include "random_source.h"

namespace ellipse_collision::test {

using quad = __float128;
using QVec3 = Eigen::Matrix<quad, 3, 1>;
using QMat3 = Eigen::Matrix<quad, 3, 3>;

/// The rotation of a quaternion normalised in quad: the oracle's own reading of the orientation.
inline QMat3 quadRotation(const Eigen::Quaterniond& q) {
  quad w = q.w(), x = q.x(), y = q.y(), z = q.z();
  const quad n = sqrtq(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  QMat3 r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 2 * (x * y + w * z),
      1 - 2 * (x * x + z * z), 2 * (y * z - w * x), 2 * (x * z - w * y), 2 * (y * z + w * x),
      1 - 2 * (x * x + y * y);
  return r;
}

/// |diag(r)^-1 R^T (p - c)|^2 of `e` at `p` in quad: <= 1 inside the ellipsoid.
inline quad ellipsoidForm(const core::Ellipsoid& e, const Eigen::Vector3d& p) {
  const QMat3 r = quadRotation(e.orientation);
  QVec3 d;
  for (int i = 0; i < 3; ++i) d[i] = static_cast<quad>(p[i]) - e.center[i];
  const QVec3 y = r.transpose() * d;
  quad sum = 0;
  for (int i = 0; i < 3; ++i) sum += (y[i] / e.radii[i]) * (y[i] / e.radii[i]);
  return sum;
}

/// A rotation drawn uniformly (a normalised quaternion of normal components).
inline Eigen::Quaterniond randomOrientation(RandomSource& random) {
  Eigen::Quaterniond q(random.normal(), random.normal(), random.normal(), random.normal());
  return q.normalized();
}

/// The placed ellipsoid {centre + map u : |u| <= 1} in the fixed frame, in quad.
struct PlacedEllipsoid {
  QVec3 centre;
  QMat3 map;
};

/// `fixed_from_frame` (read as it is, in quad) applied to the ellipsoid centre + rotation diag(radii).
inline PlacedEllipsoid placeInQuad(const QVec3& centre, const QMat3& rotation, const QVec3& radii,
                                   const Eigen::Isometry3d& fixed_from_frame) {
  QMat3 p;
  QVec3 t;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) p(i, j) = fixed_from_frame.linear()(i, j);
    t[i] = fixed_from_frame.translation()[i];
  }
  QMat3 d = QMat3::Zero();
  for (int i = 0; i < 3; ++i) d(i, i) = radii[i];
  return {p * centre + t, p * rotation * d};
}

/// A core ellipsoid placed through `fixed_from_frame`, in quad.
inline PlacedEllipsoid placeInQuad(const core::Ellipsoid& e,
                                   const Eigen::Isometry3d& fixed_from_frame) {
  QVec3 c, r;
  for (int i = 0; i < 3; ++i) c[i] = e.center[i], r[i] = e.radii[i];
  return placeInQuad(c, quadRotation(e.orientation), r, fixed_from_frame);
}

/// ((x, y) - c) in the ellipse's axes, divided by the radii, squared and summed, in quad: <= 1
/// inside the ellipse.
inline quad shadowForm(const core::Ellipse& e, quad x, quad y) {
  quad s, c;
  sincosq(static_cast<quad>(e.angle), &s, &c);
  const quad dx = x - e.center.x(), dy = y - e.center.y();
  const quad along = (c * dx + s * dy) / e.radius_x;
  const quad across = (c * dy - s * dx) / e.radius_y;
  return along * along + across * across;
}

/// What compareShadow() measured.
struct ShadowAgreement {
  /// The largest form - 1 of 512 random surface points: > 0 means a point of the ellipsoid
  /// projects outside the shadow.
  double worst_outside{-1.0};
  /// The same of the support points in 256 directions (they lie on the shadow's rim, so about 0).
  double worst_support_outside{-1.0};
  /// The largest 1 - form of the support points in 256 directions: how far the shadow's rim is
  /// from the ellipsoid's outline.
  double worst_slack{0.0};
  /// The slack allowed: 1e-9 in the form, plus what the rounding of the shadow's centre to a
  /// double costs (4 ulp(|centre|) / radius_y).
  double allowed_slack{0.0};

  bool exact() const {
    return worst_outside <= 0.0 && worst_support_outside <= 0.0 && worst_slack <= allowed_slack;
  }
};

/// `shadow` against the ellipsoid `placed`: 512 random surface points (3 normals each from
/// `random`), then the support points of 256 directions evenly spread over the circle.
inline ShadowAgreement compareShadow(const core::Ellipse& shadow, const PlacedEllipsoid& placed,
                                     RandomSource& random) {
  constexpr double kPi = 3.14159265358979323846;
  ShadowAgreement agreement;
  const double reach = shadow.center.cwiseAbs().maxCoeff();
  agreement.allowed_slack =
      1e-9 + 4.0 * (std::nextafter(reach, 2.0 * reach + 1.0) - reach) / shadow.radius_y;
  for (int k = 0; k < 512; ++k) {
    QVec3 u(random.normal(), random.normal(), random.normal());
    u /= sqrtq(u.squaredNorm());
    const QVec3 x = placed.centre + placed.map * u;
    const quad form = shadowForm(shadow, x[0], x[1]);
    agreement.worst_outside = std::max(agreement.worst_outside, static_cast<double>(form - 1));
  }
  for (int k = 0; k < 256; ++k) {
    const double angle = 2.0 * kPi * k / 256.0;
    const QVec3 w(std::cos(angle), std::sin(angle), 0.0);
    QVec3 u = placed.map.transpose() * w;
    u /= sqrtq(u.squaredNorm());
    const QVec3 x = placed.centre + placed.map * u;
    const quad form = shadowForm(shadow, x[0], x[1]);
    agreement.worst_support_outside =
        std::max(agreement.worst_support_outside, static_cast<double>(form - 1));
    agreement.worst_slack = std::max(agreement.worst_slack, static_cast<double>(1 - form));
  }
  return agreement;
}

}  // namespace ellipse_collision::test
