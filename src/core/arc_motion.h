#pragma once

#include <cmath>

namespace ellipse_collision::core::detail {

/// sin(x) / x, 1 at 0.
template <typename T>
T sinc(T x) {
  return x == T(0) ? T(1) : std::sin(x) / x;
}

/// A displacement in the plane [m].
template <typename T>
struct Displacement {
  T x, y;
};

/// How far a point moves in `t` [s] when its velocity (vx, vy) [m/s] at t = 0 turns at
/// `turn_rate` [rad/s] (a point of a frame that turns, on an arc about the frame's instantaneous
/// centre of rotation): (vx + i vy) (e^{i w t} - 1) / (i w), evaluated as t sinc(w t) and
/// t sin(w t / 2) sinc(w t / 2) (= (1 - cos(w t)) / w) so that a tiny turn rate, or a far centre,
/// loses no precision (no 1 - cos, no division by w). The one formula for poseAfter() and the
/// rotating pairs (rotating_contact.h); T is double, or long double where they need the digits.
template <typename T>
Displacement<T> arcDisplacement(T vx, T vy, T turn_rate, T t) {
  const T turn = turn_rate * t;
  const T along = t * sinc(turn);                                      // sin(w t) / w
  const T across = t * std::sin(T(0.5) * turn) * sinc(T(0.5) * turn);  // (1 - cos(w t)) / w
  return {along * vx - across * vy, across * vx + along * vy};
}

}  // namespace ellipse_collision::core::detail
