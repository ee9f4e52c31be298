// Minimum-area enclosing ellipses of points given as an (N, 2) float64 array. The core validates
// the points itself (EnclosingEllipse::error names the point and value): its error is raised as
// ValueError; Degenerate sets (collinear points) are an answer, not an error.
#include <string>
#include <vector>

#include "bindings.h"
#include "ellipse_collision/core/enclosing_ellipse.h"
#include "ellipse_rows.h"
#include "refusal.h"

namespace ellipse_collision::python {

namespace py = pybind11;

namespace {

std::vector<Eigen::Vector2d> pointsOf(const py::array& array) {
  requireFloat64Rows(array, "points", 2, "x, y");
  const auto rows = array.unchecked<double, 2>();
  std::vector<Eigen::Vector2d> points;
  points.reserve(static_cast<std::size_t>(rows.shape(0)));
  for (py::ssize_t i = 0; i < rows.shape(0); ++i) points.emplace_back(rows(i, 0), rows(i, 1));
  return points;
}

core::EnclosingEllipse answered(core::EnclosingEllipse result) {
  if (result.status == core::EnclosingStatus::Error) refuseIfInvalid(result.error);
  return result;
}

const char* statusName(core::EnclosingStatus status) {
  switch (status) {
    case core::EnclosingStatus::Ok:
      return "ok";
    case core::EnclosingStatus::Degenerate:
      return "degenerate";
    case core::EnclosingStatus::Error:
      break;
  }
  return "error";
}

}  // namespace

void bindEnclosingFunctions(py::module_& module) {
  py::class_<core::EnclosingEllipse>(
      module, "EnclosingEllipse",
      "An enclosing ellipse (status 'ok': ellipse contains every point, certified) or, for "
      "points that span no area (status 'degenerate'), the segment [segment_start, segment_end] "
      "[m] and half_width [m] that hold them.")
      .def_property_readonly("status",
                             [](const core::EnclosingEllipse& e) { return statusName(e.status); })
      .def_property_readonly("ellipse",
                             [](const core::EnclosingEllipse& e) -> py::object {
                               if (!e.ok()) return py::none();
                               return py::cast(e.ellipse);
                             })
      .def_property_readonly(
          "segment_start",
          [](const core::EnclosingEllipse& e) { return pointTuple(e.segment_start); })
      .def_property_readonly(
          "segment_end", [](const core::EnclosingEllipse& e) { return pointTuple(e.segment_end); })
      .def_readonly("half_width", &core::EnclosingEllipse::half_width)
      .def_readonly("area_excess_bound", &core::EnclosingEllipse::area_excess_bound);

  module.def(
      "minimum_area_ellipse",
      [](const py::array& points) {
        std::vector<Eigen::Vector2d> copied = pointsOf(points);
        py::gil_scoped_release release;
        return answered(core::minimumAreaEllipse(copied));
      },
      py::arg("points"),
      "The minimum-area ellipse containing every point of an (N, 2) float64 array [m] (an "
      "EnclosingEllipse; area within about 1e-9 of the minimum).");
  module.def(
      "enclosing_ellipse_with_min_radius",
      [](const py::array& points, double min_radius) {
        std::vector<Eigen::Vector2d> copied = pointsOf(points);
        py::gil_scoped_release release;
        return answered(core::enclosingEllipseWithMinRadius(copied, min_radius));
      },
      py::arg("points"), py::arg("min_radius"),
      "An ellipse containing every point with both radii >= min_radius [m], also for one point "
      "or collinear points (status always 'ok').");
}

}  // namespace ellipse_collision::python
