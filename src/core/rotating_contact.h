#pragma once

#include <Eigen/Core>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"

namespace ellipse_collision::core::detail {

/// A pair in the frame of a's centre, so that centres 1e6 m out lose no precision: `a` centred at
/// the origin and turning at `wa`, `b` centred at b.center + w t and turning at `wb`.
struct RotatingPair {
  Ellipse a;
  Ellipse b;
  Eigen::Vector2d w{0.0, 0.0};  ///< v_b - v_a [m/s]
  double wa{0.0}, wb{0.0};      ///< angular velocities [rad/s]

  Ellipse aAt(double t) const;
  Ellipse bAt(double t) const;
};

/// Resolution of the first contact of a rotating pair, relative to the horizon: the answer is
/// never later than the true first contact and, where the pair overlaps within this of it, no more
/// than this earlier.
inline constexpr double kRotationResolution = 2.5e-10;
/// Safety cap on the steps; the tests and the benchmark count the pairs that reach it (none).
inline constexpr int kMaxRotationSteps = 20000;

/// What one call did, for the tests and the benchmark.
struct RotationWork {
  int distance_calls{0};
  bool capped{false};
};

/// firstContact() of a rotating pair (see rotating_contact.cpp). `work`, when given, receives the
/// work done.
FirstContact rotatingContact(const RotatingPair& pair, double horizon, RotationWork* work = nullptr);

}  // namespace ellipse_collision::core::detail
