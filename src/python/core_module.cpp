// ellipse_collision.core: the ROS-free core for Python (doc/python.md). Every input is validated
// by the core's own rules (invalidReason() and friends) and refused with ValueError naming the
// field and value, so no call from Python reaches the core with a value it does not accept.
#include "bindings.h"

PYBIND11_MODULE(core, module) {
  module.doc() =
      "2D ellipse collision checking: overlap, contact scale, distance, first contact of moving "
      "ellipses, minimum-area enclosing ellipses and scene checks (the C++ core of "
      "ellipse_collision). Batch forms take (N, 5) float64 arrays of [x, y, radius_x, radius_y, "
      "angle] rows.";
  ellipse_collision::python::bindValueTypes(module);
  ellipse_collision::python::bindPairFunctions(module);
  ellipse_collision::python::bindBatchFunctions(module);
  ellipse_collision::python::bindEllipseBatch(module);
  ellipse_collision::python::bindEnclosingFunctions(module);
  ellipse_collision::python::bindSceneFunctions(module);
}
