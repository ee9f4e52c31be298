// core.EllipseBatch: a fixed set of ellipses, prepared once and kept as the core's
// structure of arrays (core::EllipseBatch), for many overlap questions against the same set (a
// map's obstacles against candidate robot poses): each question culls the far ellipses in SIMD
// registers (AVX2 where the processor has it) and tests the few left exactly, the same answers
// as overlap() bit for bit. For one-off pairs overlap_batch() is the right call: preparing the
// set costs about what testing each ellipse once does.
#include <pybind11/numpy.h>

#include <cstdint>
#include <string>

#include "bindings.h"
#include "ellipse_collision/core/batch_overlap.h"
#include "ellipse_rows.h"

namespace ellipse_collision::python {

namespace py = pybind11;

namespace {

/// The batch of the rows of `array` ((N, 5) float64); the first invalid row is refused with
/// ValueError naming `name`, the row, the field and the value.
core::EllipseBatch batchOfRows(const py::array& array, const char* name) {
  const EllipseRows rows(array, name);
  core::EllipseBatch batch;
  batch.reserve(static_cast<std::size_t>(rows.size()));
  for (py::ssize_t i = 0; i < rows.size(); ++i) {
    if (!batch.add(rows[i]).empty()) rows.refuseRow(i);
  }
  return batch;
}

/// An (N,) bool array of the bytes `fill(out)` writes.
template <typename Fill>
py::array_t<bool> boolArray(std::size_t size, Fill fill) {
  py::array_t<std::uint8_t> bytes(static_cast<py::ssize_t>(size));
  std::uint8_t* out = bytes.mutable_data();
  {
    py::gil_scoped_release release;
    fill(out);
  }
  // The core writes 0 or 1: a view of the same bytes as numpy bool, no copy.
  return py::array_t<bool>(bytes.attr("view")(py::dtype::of<bool>()));
}

}  // namespace

void bindEllipseBatch(py::module_& module) {
  py::class_<core::EllipseBatch>(
      module, "EllipseBatch",
      "A fixed set of ellipses for many overlap questions: EllipseBatch(rows), rows an (N, 5) "
      "float64 array [x, y, radius_x, radius_y, angle], validated and prepared once. "
      "overlap_with(ellipse) and overlap_rows(batch) answer as overlap() does, bit for bit.")
      .def(py::init([](const py::array& rows) { return batchOfRows(rows, "rows"); }),
           py::arg("rows"))
      .def("__len__", &core::EllipseBatch::size)
      .def(
          "overlap_with",
          [](const core::EllipseBatch& batch, const core::Ellipse& ellipse) {
            return boolArray(batch.size(), [&](std::uint8_t* out) {
              // The Ellipse was validated when it was made: no refusal is possible here.
              core::overlapOneToMany(ellipse, batch, out);
            });
          },
          py::arg("ellipse"),
          "overlap(ellipse, e) for every ellipse e of the batch: an (N,) bool array.")
      .def(
          "overlap_rows",
          [](const core::EllipseBatch& batch, const core::EllipseBatch& other) {
            if (other.size() != batch.size()) {
              throw py::value_error("this batch has " + std::to_string(batch.size()) +
                                    " ellipses and the other " + std::to_string(other.size()) +
                                    ": one pair per row, the same number in both");
            }
            return boolArray(batch.size(), [&](std::uint8_t* out) {
              core::overlapBatch(batch, other, out);
            });
          },
          py::arg("other"),
          "overlap(self[i], other[i]) for every row i: an (N,) bool array.")
      .def("__repr__", [](const core::EllipseBatch& batch) {
        return "EllipseBatch(" + std::to_string(batch.size()) + " ellipses)";
      });
}

}  // namespace ellipse_collision::python
