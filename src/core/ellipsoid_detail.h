#pragma once

// Shared by the ellipsoid's shadow (ellipsoid.cpp) and its fit (enclosing_ellipsoid.cpp), which
// certify in long double against the same rotation. Internal to the core (src/core).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rounded_up.h"

namespace ellipse_collision::core::detail {

using LongMat3 = Eigen::Matrix<long double, 3, 3>;

/// The rotation of the normalised `orientation`, in long double: what R(orientation) means for an
/// Ellipsoid wherever it is certified.
LongMat3 rotationOf(const Eigen::Quaterniond& orientation);

}  // namespace ellipse_collision::core::detail
