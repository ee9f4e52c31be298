// The pair functions of the core on two Ellipse objects. Ellipses are valid by construction
// (value_types.cpp); a motion and horizon are checked here by invalidMotionReason().
#include "bindings.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/overlap.h"
#include "refusal.h"

namespace ellipse_collision::python {

namespace py = pybind11;

void bindPairFunctions(py::module_& module) {
  module.def("overlap", &core::overlap, py::arg("a"), py::arg("b"),
             "True iff the closed ellipses share a point (containment is a collision); exact "
             "near tangency.");
  module.def("contact_scale", &core::contactScale, py::arg("a"), py::arg("b"),
             "t*: the factor by which both ellipses, scaled about their own centres, just touch. "
             "They overlap iff t* <= 1; coincident centres give 0.");
  module.def("distance", &core::distance, py::arg("a"), py::arg("b"),
             "Minimum distance [m] between the ellipses and its witness points (a Clearance); "
             "distance 0 and separated False when they overlap.");
  module.def(
      "first_contact",
      [](const core::Ellipse& a, const core::Motion& motion_a, const core::Ellipse& b,
         const core::Motion& motion_b, double horizon) {
        refuseIfInvalid(core::invalidMotionReason(a, motion_a, b, motion_b, horizon));
        // Rotating pairs may take up to ~40 ms: other Python threads run meanwhile.
        py::gil_scoped_release release;
        return core::firstContact(a, motion_a, b, motion_b, horizon);
      },
      py::arg("a"), py::arg("motion_a"), py::arg("b"), py::arg("motion_b"), py::arg("horizon"),
      "The first time t in [0, horizon] [s] at which a and b, each moving rigidly by its Motion, "
      "share a point (a FirstContact). Exact for translations, never late for rotations.");
}

}  // namespace ellipse_collision::python
