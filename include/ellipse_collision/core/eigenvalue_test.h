#pragma once

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// Eigenvalue test (Gilitschenski & Hanebeck 2012; Perram & Wertheim 1985) deciding overlap only.
/// It maximises the concave Q(s) and stops as soon as a lower bound exceeds 1 (separate) or an
/// upper bound from the bracketing tangents is at most 1 (overlap), so it is cheaper than
/// contactScale().
bool eigenvalueOverlap(const Ellipse& a, const Ellipse& b);

/// t*: the factor by which both ellipses, scaled about their own centres, just touch.
/// The ellipses overlap iff t* <= 1; coincident centres give 0. Computed as sqrt(max_s Q(s)).
double contactScale(const Ellipse& a, const Ellipse& b);

}  // namespace ellipse_collision::core
