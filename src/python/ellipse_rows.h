#pragma once

#include <pybind11/numpy.h>

#include <string>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::python {

/// Raises ValueError naming `name` ("a: shape (3, 4), expected (N, 5): rows [COLUMNS]", "a: dtype
/// int64, expected float64") unless `array` is a 2-dimensional float64 array with `columns`
/// columns; `column_names` lists them for the message.
void requireFloat64Rows(const pybind11::array& array, const char* name, pybind11::ssize_t columns,
                        const char* column_names);

/// An (N, 5) float64 numpy array of ellipses, one row [x, y, radius_x, radius_y, angle] each,
/// read in place (any strides, no copy). Reading a row needs no GIL: the caller keeps the array
/// alive for as long as the rows are read.
class EllipseRows {
 public:
  /// Raises ValueError naming `name` unless `array` is an (N, 5) float64 array
  /// (requireFloat64Rows()).
  EllipseRows(const pybind11::array& array, const char* name);

  pybind11::ssize_t size() const { return rows_; }
  const char* name() const { return name_; }

  /// Row `i` as an ellipse, unvalidated (see core::isValid()).
  core::Ellipse operator[](pybind11::ssize_t i) const {
    const char* row = data_ + i * row_stride_;
    core::Ellipse ellipse;
    ellipse.center = {field(row, 0), field(row, 1)};
    ellipse.radius_x = field(row, 2);
    ellipse.radius_y = field(row, 3);
    ellipse.angle = field(row, 4);
    return ellipse;
  }

  /// Raises ValueError "NAME[i]: REASON" with the core's invalidReason() of row `i`.
  [[noreturn]] void refuseRow(pybind11::ssize_t i) const;

 private:
  double field(const char* row, int column) const {
    return *reinterpret_cast<const double*>(row + column * column_stride_);
  }

  const char* name_;
  const char* data_{nullptr};
  pybind11::ssize_t rows_{0};
  pybind11::ssize_t row_stride_{0};
  pybind11::ssize_t column_stride_{0};
};

/// Raises ValueError unless `a` and `b` have the same number of rows.
void requireSameRows(const EllipseRows& a, const EllipseRows& b);

}  // namespace ellipse_collision::python
