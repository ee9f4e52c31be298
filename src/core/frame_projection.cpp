#include "ellipse_collision/core/frame_projection.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::core {
namespace {

/// a*d - b*c with Kahan's fma trick: accurate to a few ulps even when the products cancel, which
/// is exactly the nearly edge-on case where the determinant decides the minor radius.
double determinant2(double a, double b, double c, double d) {
  const double w = b * c;
  const double rounding_error_of_w = std::fma(-b, c, w);
  return std::fma(a, d, -w) + rounding_error_of_w;
}

}  // namespace

namespace {

// A tilt can thin a valid ellipse below kMinRadius, a transform move it beyond kMaxCoordinate.
ProjectionResult checkedProjection(ProjectionResult result, const std::string& name) {
  const std::string unusable = invalidReason(result.ellipse);
  if (!unusable.empty()) {
    result.error = "ellipse '" + name + "': its projection is out of range (" + unusable + ")";
  }
  return result;
}

}  // namespace

ProjectionResult projectToPlane(const Ellipse& in_frame, const Eigen::Isometry3d& fixed_from_frame,
                                const std::string& name) {
  ProjectionResult result;
  const std::string invalid = invalidReason(in_frame);
  if (!invalid.empty()) {
    result.error = "ellipse '" + name + "': " + invalid;
    return result;
  }
  if (!fixed_from_frame.matrix().allFinite()) {
    result.error = "ellipse '" + name + "': the transform of its frame is not finite";
    return result;
  }

  const Eigen::Matrix2d plane_block = fixed_from_frame.linear().topLeftCorner<2, 2>();
  const Eigen::Matrix3d& rotation = fixed_from_frame.linear();
  if (rotation(2, 0) == 0.0 && rotation(2, 1) == 0.0 && rotation(0, 2) == 0.0 &&
      rotation(1, 2) == 0.0 && rotation(2, 2) > 0.0) {
    // A rotation about z only (every planar robot's frames): the projection keeps the radii
    // exactly and turns the ellipse by the yaw, so no rounding can push a radius out of range.
    result.ellipse.center =
        fixed_from_frame.translation().head<2>() + plane_block * in_frame.center;
    // Same conventions as the general case: radius_x the major radius, angle in (-pi/2, pi/2].
    const bool swap = in_frame.radius_y > in_frame.radius_x;
    result.ellipse.radius_x = swap ? in_frame.radius_y : in_frame.radius_x;
    result.ellipse.radius_y = swap ? in_frame.radius_x : in_frame.radius_y;
    double angle = std::remainder(
        in_frame.angle + std::atan2(rotation(1, 0), rotation(0, 0)) + (swap ? M_PI / 2 : 0.0),
        M_PI);
    if (angle <= -M_PI / 2) angle += M_PI;
    result.ellipse.angle = angle;
    return checkedProjection(std::move(result), name);
  }
  const double c = std::cos(in_frame.angle);
  const double s = std::sin(in_frame.angle);
  Eigen::Matrix2d shape;  // R(angle) diag(radius_x, radius_y)
  shape << c * in_frame.radius_x, -s * in_frame.radius_y, s * in_frame.radius_x,
      c * in_frame.radius_y;
  const Eigen::Matrix2d a = plane_block * shape;

  // Closed-form 2x2 SVD: A = E*I + F*diag(1,-1) + G*[0 1; 1 0] + H*[0 -1; 1 0]; then
  // A = R(phi) diag(Q + R, Q - R) R(theta) with Q = |(E, H)|, R = |(F, G)|,
  // phi = (atan2(G, F) + atan2(H, E)) / 2. The sign of Q - R only mirrors the unit disk.
  const double e = 0.5 * (a(0, 0) + a(1, 1));
  const double f = 0.5 * (a(0, 0) - a(1, 1));
  const double g = 0.5 * (a(1, 0) + a(0, 1));
  const double h = 0.5 * (a(1, 0) - a(0, 1));
  const double q = std::hypot(e, h);
  const double r = std::hypot(f, g);
  const double major = q + r;
  // |Q - R| cancels when nearly edge-on; |det(A)| / major = |det(P)| radius_x radius_y / major
  // does not (the division comes first so that large radii do not overflow).
  const double det_p =
      determinant2(plane_block(0, 0), plane_block(0, 1), plane_block(1, 0), plane_block(1, 1));
  const double minor = std::abs(det_p) * in_frame.radius_x * (in_frame.radius_y / major);

  const double smaller_radius = std::min(in_frame.radius_x, in_frame.radius_y);
  if (!(minor >= kMinProjectedThinning * smaller_radius)) {
    result.error = "ellipse '" + name +
                   "': its frame is seen edge-on from the fixed frame's xy-plane (projected minor "
                   "radius " +
                   formatNumber(minor) + " m is below " + formatNumber(kMinProjectedThinning) +
                   " times its smaller radius " + formatNumber(smaller_radius) + " m)";
    return result;
  }

  double angle = 0.5 * (std::atan2(g, f) + std::atan2(h, e));
  // An ellipse is symmetric under a half turn: report the angle in (-pi/2, pi/2].
  if (angle > M_PI / 2) angle -= M_PI;
  if (angle <= -M_PI / 2) angle += M_PI;

  result.ellipse.center = fixed_from_frame.translation().head<2>() + plane_block * in_frame.center;
  result.ellipse.radius_x = major;
  result.ellipse.radius_y = minor;
  result.ellipse.angle = angle;
  return checkedProjection(std::move(result), name);
}

}  // namespace ellipse_collision::core
