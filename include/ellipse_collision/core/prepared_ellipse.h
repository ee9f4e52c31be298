#pragma once

#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/overlap.h"

namespace ellipse_collision::core {

/// An ellipse with everything its pair tests need from it alone, computed once (one sincos, two
/// divisions, two square roots): build one per ellipse and check cycle, then every pair test
/// does only pair work. The prepared and plain APIs give bit-identical answers.
class PreparedEllipse {
 public:
  explicit PreparedEllipse(const Ellipse& ellipse);

  const Ellipse& ellipse() const { return ellipse_; }
  double cosAngle() const { return cos_angle_; }
  double sinAngle() const { return sin_angle_; }
  double inverseRadiusX() const { return inverse_radius_x_; }   ///< [1/m]
  double inverseRadiusY() const { return inverse_radius_y_; }   ///< [1/m]
  double boundingRadius() const { return bounding_radius_; }    ///< [m]
  double inscribedRadius() const { return inscribed_radius_; }  ///< [m]
  const BoundingBox& box() const { return box_; }               ///< boundingBox(ellipse())

 private:
  // The bounding-circle test, which decides most pairs, reads the first 48 bytes only.
  Ellipse ellipse_;
  double bounding_radius_;
  double inscribed_radius_;
  double cos_angle_;
  double sin_angle_;
  double inverse_radius_x_;
  double inverse_radius_y_;
  BoundingBox box_;
};

namespace detail {

/// overlap() of prepared ellipses whose bounding circles meet.
bool overlapOfNearPair(const PreparedEllipse& a, const PreparedEllipse& b);

}  // namespace detail

/// overlap(a.ellipse(), b.ellipse()), without the per-ellipse work.
inline bool overlap(const PreparedEllipse& a, const PreparedEllipse& b) {
  return !detail::circlesApart(a.ellipse().center, b.ellipse().center,
                               a.boundingRadius() + b.boundingRadius()) &&
         detail::overlapOfNearPair(a, b);
}

/// contactScale(a.ellipse(), b.ellipse()), without the per-ellipse work.
double contactScale(const PreparedEllipse& a, const PreparedEllipse& b);

}  // namespace ellipse_collision::core
