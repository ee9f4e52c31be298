#pragma once

#include "ellipse_collision/core/broadphase.h"

namespace ellipse_collision::core::detail {

/// boundingBox() from the ellipse's cos and sin, for callers that already have them.
BoundingBox boundingBoxFromTrig(const Ellipse& ellipse, double cos_angle, double sin_angle);

}  // namespace ellipse_collision::core::detail
