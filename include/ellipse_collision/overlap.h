#pragma once

#include "ellipse_collision/ellipse.h"

namespace ellipse_collision {

/// True iff the closed ellipses share a point (containment is a collision). Cheap exact bounding
/// and inscribed circle tests first, then the polygonal early-out, and the eigenvalue test whenever
/// those cannot prove the answer. Both ellipses must be valid (see invalidReason()).
bool overlap(const Ellipse& a, const Ellipse& b);

}  // namespace ellipse_collision
