#pragma once

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// Eigenvalue test (Gilitschenski & Hanebeck 2012; Perram & Wertheim 1985) deciding overlap only.
/// It maximises the concave Q(s) and stops as soon as a lower bound exceeds 1 (separate) or an
/// upper bound from the bracketing tangents is at most 1 (overlap), so it is cheaper than
/// contactScale().
bool eigenvalueOverlap(const Ellipse& a, const Ellipse& b);

/// t*: the factor by which both ellipses, scaled about their own centres, just touch.
/// The ellipses overlap iff t* <= 1; coincident centres give 0. Computed as sqrt(max_s Q(s)),
/// the maximiser as the one positive root of a quartic (Halley's steps, bracketed), with the
/// certified maximisation of Q behind it for the rare pair whose quartic is not done in a dozen
/// steps or overflows. Accuracy against a quad-precision oracle: test_overlap_accuracy.cpp.
double contactScale(const Ellipse& a, const Ellipse& b);

}  // namespace ellipse_collision::core
