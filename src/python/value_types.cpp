// The value types shared by the module's functions. An Ellipse is validated when it is made and
// cannot be changed afterwards, so every function may hand it to the core as it is.
#include <pybind11/stl.h>

#include <string>

#include "bindings.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/number_format.h"
#include "refusal.h"

namespace ellipse_collision::python {

namespace py = pybind11;
using core::formatNumber;

void bindValueTypes(py::module_& module) {
  py::class_<core::Ellipse>(module, "Ellipse",
                            "A closed 2D ellipse: centre (x, y) [m], semi-axes radius_x and "
                            "radius_y [m] along its own axes, angle [rad] counter-clockwise from "
                            "the frame's x axis to its own x axis. Immutable; validated when made.")
      .def(py::init([](double x, double y, double radius_x, double radius_y, double angle) {
             core::Ellipse ellipse;
             ellipse.center = {x, y};
             ellipse.radius_x = radius_x;
             ellipse.radius_y = radius_y;
             ellipse.angle = angle;
             refuseIfInvalid(core::invalidReason(ellipse));
             return ellipse;
           }),
           py::arg("x"), py::arg("y"), py::arg("radius_x"), py::arg("radius_y"),
           py::arg("angle") = 0.0)
      .def_property_readonly("x", [](const core::Ellipse& e) { return e.center.x(); })
      .def_property_readonly("y", [](const core::Ellipse& e) { return e.center.y(); })
      .def_readonly("radius_x", &core::Ellipse::radius_x)
      .def_readonly("radius_y", &core::Ellipse::radius_y)
      .def_readonly("angle", &core::Ellipse::angle)
      .def(
          "as_row",
          [](const core::Ellipse& e) {
            return py::make_tuple(e.center.x(), e.center.y(), e.radius_x, e.radius_y, e.angle);
          },
          "(x, y, radius_x, radius_y, angle): one row of the batch functions' arrays.")
      .def("__repr__", [](const core::Ellipse& e) {
        return "Ellipse(x=" + formatNumber(e.center.x()) + ", y=" + formatNumber(e.center.y()) +
               ", radius_x=" + formatNumber(e.radius_x) + ", radius_y=" + formatNumber(e.radius_y) +
               ", angle=" + formatNumber(e.angle) + ")";
      });

  py::class_<core::Motion>(module, "Motion",
                           "Rigid planar motion: centre velocity (vx, vy) [m/s] and angular "
                           "velocity about the centre [rad/s], counter-clockwise.")
      .def(py::init([](double vx, double vy, double angular_velocity) {
             core::Motion motion;
             motion.velocity = {vx, vy};
             motion.angular_velocity = angular_velocity;
             return motion;
           }),
           py::arg("vx") = 0.0, py::arg("vy") = 0.0, py::arg("angular_velocity") = 0.0)
      .def_property_readonly("vx", [](const core::Motion& m) { return m.velocity.x(); })
      .def_property_readonly("vy", [](const core::Motion& m) { return m.velocity.y(); })
      .def_readonly("angular_velocity", &core::Motion::angular_velocity)
      .def("__repr__", [](const core::Motion& m) {
        return "Motion(vx=" + formatNumber(m.velocity.x()) +
               ", vy=" + formatNumber(m.velocity.y()) +
               ", angular_velocity=" + formatNumber(m.angular_velocity) + ")";
      });

  py::class_<core::Clearance>(module, "Clearance",
                              "distance()'s answer: separated, distance [m] and the witness "
                              "points point_a, point_b [m] (meaningless, at the origin, when the "
                              "ellipses overlap).")
      .def_readonly("separated", &core::Clearance::separated)
      .def_readonly("distance", &core::Clearance::distance)
      .def_property_readonly("point_a",
                             [](const core::Clearance& c) { return pointTuple(c.point_a); })
      .def_property_readonly("point_b",
                             [](const core::Clearance& c) { return pointTuple(c.point_b); })
      .def("__repr__", [](const core::Clearance& c) {
        return std::string("Clearance(separated=") + (c.separated ? "True" : "False") +
               ", distance=" + formatNumber(c.distance) + ", point_a=(" +
               formatNumber(c.point_a.x()) + ", " + formatNumber(c.point_a.y()) + "), point_b=(" +
               formatNumber(c.point_b.x()) + ", " + formatNumber(c.point_b.y()) + "))";
      });

  py::class_<core::FirstContact>(module, "FirstContact",
                                 "first_contact()'s answer: contact, and its first time [s] "
                                 "(0 when contact is False).")
      .def_readonly("contact", &core::FirstContact::contact)
      .def_readonly("time", &core::FirstContact::time)
      .def("__repr__", [](const core::FirstContact& c) {
        return std::string("FirstContact(contact=") + (c.contact ? "True" : "False") +
               ", time=" + formatNumber(c.time) + ")";
      });
}

}  // namespace ellipse_collision::python
