#pragma once

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// What the polygonal test could prove. `Unknown` means it ran out of iterations: it is never
/// a "no collision".
enum class PolygonalResult { Overlap, Separate, Unknown };

const char* toString(PolygonalResult result);

/// Default iteration cap of polygonalTest(); each iteration halves the angular width of the arcs
/// examined.
constexpr int kDefaultPolygonalIterations = 6;

/// Iteration cap of overlap()'s polygonal stage: level 0 (the inscribed and circumscribed
/// parallelograms) only. Measured with caps 0..8 on scene-like, near and near-tangent pairs
/// (bench/bench_pair_tests.cpp): what level 0 cannot decide, the eigenvalue test's certified exits
/// decide faster than further bisection.
constexpr int kOverlapPolygonalIterations = 0;

/// Niemitalo's polygonal test: the larger ellipse is mapped to the unit circle, and the rim of the
/// other is enclosed between inscribed and circumscribed polygons that are refined by bisection
/// around the part of the rim near the circle, at most `max_iterations` times. A hit on an
/// inscribed polygon proves overlap, a miss of every circumscribed triangle proves separation.
/// Decisions within a relative rounding margin of the rim are left `Unknown`.
PolygonalResult polygonalTest(const Ellipse& a, const Ellipse& b,
                              int max_iterations = kDefaultPolygonalIterations);

}  // namespace ellipse_collision::core
