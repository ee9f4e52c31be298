#pragma once

// The Python module ellipse_collision.core (core_module.cpp) is assembled from one binding
// function per part of the ROS-free core; each file binds its part and nothing else.
#include <pybind11/pybind11.h>

#include <Eigen/Core>

namespace ellipse_collision::python {

/// Ellipse, Motion and the results of the pair functions (value_types.cpp).
void bindValueTypes(pybind11::module_& module);
/// overlap, contact_scale, distance and first_contact of one pair (pair_functions.cpp).
void bindPairFunctions(pybind11::module_& module);
/// The same on N pairs given as numpy arrays, looping in C++ without the GIL (batch_functions.cpp).
void bindBatchFunctions(pybind11::module_& module);
/// EllipseBatch: a fixed set of ellipses for many overlap questions (ellipse_batch.cpp).
void bindEllipseBatch(pybind11::module_& module);
/// minimum_area_ellipse and enclosing_ellipse_with_min_radius of points (enclosing_functions.cpp).
void bindEnclosingFunctions(pybind11::module_& module);
/// check_scene of named ellipses (scene_functions.cpp).
void bindSceneFunctions(pybind11::module_& module);

/// A point [m] as Python sees it: the tuple (x, y).
inline pybind11::tuple pointTuple(const Eigen::Vector2d& point) {
  return pybind11::make_tuple(point.x(), point.y());
}

}  // namespace ellipse_collision::python
