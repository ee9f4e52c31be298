#include "relative_shape.h"

#include <cmath>
#include <tuple>

namespace ellipse_collision::detail {

RelativeShape relativeShape(const Ellipse& unit, const Ellipse& other) {
  const Eigen::Vector2d offset = other.center - unit.center;
  const double cos_unit = std::cos(unit.angle);
  const double sin_unit = std::sin(unit.angle);
  const double inv_rx = 1.0 / unit.radius_x;
  const double inv_ry = 1.0 / unit.radius_y;

  RelativeShape shape;
  shape.center.x() = (cos_unit * offset.x() + sin_unit * offset.y()) * inv_rx;
  shape.center.y() = (cos_unit * offset.y() - sin_unit * offset.x()) * inv_ry;

  // The relative angle is taken before the trigonometry so that equal angles give an exact
  // identity rotation.
  const double relative_angle = other.angle - unit.angle;
  const double c = std::cos(relative_angle);
  const double s = std::sin(relative_angle);
  // axes = diag(1/rx, 1/ry) * R(relative_angle) * diag(other.rx, other.ry)
  shape.axes << c * other.radius_x * inv_rx, -s * other.radius_y * inv_rx,
      s * other.radius_x * inv_ry, c * other.radius_y * inv_ry;
  // axes^-1 = diag(1/other.rx, 1/other.ry) * R(-relative_angle) * diag(rx, ry)
  const double inv_orx = 1.0 / other.radius_x;
  const double inv_ory = 1.0 / other.radius_y;
  shape.inverse_axes << c * unit.radius_x * inv_orx, s * unit.radius_y * inv_orx,
      -s * unit.radius_x * inv_ory, c * unit.radius_y * inv_ory;
  shape.determinant = (other.radius_x * inv_rx) * (other.radius_y * inv_ry);
  return shape;
}

namespace {

bool precedesAsUnit(const Ellipse& a, const Ellipse& b) {
  return std::make_tuple(a.radius_x * a.radius_y, a.radius_x, a.radius_y, a.angle, a.center.x(),
                         a.center.y()) >= std::make_tuple(b.radius_x * b.radius_y, b.radius_x,
                                                          b.radius_y, b.angle, b.center.x(),
                                                          b.center.y());
}

}  // namespace

RelativeShape canonicalRelativeShape(const Ellipse& a, const Ellipse& b) {
  return precedesAsUnit(a, b) ? relativeShape(a, b) : relativeShape(b, a);
}

}  // namespace ellipse_collision::detail
