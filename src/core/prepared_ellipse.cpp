#include "ellipse_collision/core/prepared_ellipse.h"

#include "broadphase_detail.h"
#include "relative_shape.h"

namespace ellipse_collision::core {

PreparedEllipse::PreparedEllipse(const Ellipse& ellipse) : ellipse_(ellipse) {
  // The very factors the plain API computes per pair, so that both give identical answers.
  const detail::FrameFactors factors = detail::frameFactors(ellipse);
  cos_angle_ = factors.cos_angle;
  sin_angle_ = factors.sin_angle;
  inverse_radius_x_ = factors.inverse_radius_x;
  inverse_radius_y_ = factors.inverse_radius_y;
  bounding_radius_ = ellipse_collision::core::boundingRadius(ellipse);
  inscribed_radius_ = ellipse_collision::core::inscribedRadius(ellipse);
  box_ = detail::boundingBoxFromTrig(ellipse, cos_angle_, sin_angle_);
}

}  // namespace ellipse_collision::core
