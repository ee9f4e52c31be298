#include "ellipse_rows.h"

#include <string>

#include "refusal.h"

namespace ellipse_collision::python {

namespace py = pybind11;

namespace {

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t axis = 0; axis < array.ndim(); ++axis) {
    if (axis > 0) text += ", ";
    text += std::to_string(array.shape(axis));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

}  // namespace

void requireFloat64Rows(const py::array& array, const char* name, py::ssize_t columns,
                        const char* column_names) {
  // Converting another dtype silently would hide a caller's mistake (integer radii from a file
  // read as int64, float32 rounding) and copy the whole array: refused instead.
  if (!py::array_t<double>::check_(array)) {
    throw py::value_error(std::string(name) + ": dtype " + std::string(py::str(array.dtype())) +
                          ", expected float64");
  }
  if (array.ndim() != 2 || array.shape(1) != columns) {
    throw py::value_error(std::string(name) + ": shape " + shapeText(array) + ", expected (N, " +
                          std::to_string(columns) + "): rows [" + column_names + "]");
  }
}

EllipseRows::EllipseRows(const py::array& array, const char* name) : name_(name) {
  requireFloat64Rows(array, name, 5, "x, y, radius_x, radius_y, angle");
  data_ = static_cast<const char*>(array.data());
  rows_ = array.shape(0);
  row_stride_ = array.strides(0);
  column_stride_ = array.strides(1);
}

void EllipseRows::refuseRow(py::ssize_t i) const {
  refuseIfInvalid(core::invalidReason((*this)[i]),
                  std::string(name_) + "[" + std::to_string(i) + "]: ");
  throw py::value_error(std::string(name_) + "[" + std::to_string(i) + "] is invalid");
}

void requireSameRows(const EllipseRows& a, const EllipseRows& b) {
  if (a.size() != b.size()) {
    throw py::value_error(std::string(a.name()) + " has " + std::to_string(a.size()) +
                          " rows and " + b.name() + " " + std::to_string(b.size()) +
                          ": one pair per row, the same number of rows in both");
  }
}

}  // namespace ellipse_collision::python
