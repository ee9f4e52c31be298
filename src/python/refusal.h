#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace ellipse_collision::python {

/// Raises ValueError with `reason` (one of the core's own messages, such as invalidReason()'s
/// "radius_x = -1 must be > 0") after `prefix` ("a[3]: "), unless `reason` is empty.
inline void refuseIfInvalid(const std::string& reason, const std::string& prefix = "") {
  if (!reason.empty()) throw pybind11::value_error(prefix + reason);
}

}  // namespace ellipse_collision::python
