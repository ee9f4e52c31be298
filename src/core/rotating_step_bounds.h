#pragma once

// The steps of rotatingContact() that no contact can pass: the bounds of one pair (StepBounds)
// and the second-order step from a separation (doc/rotating_contact.md). Internal to the core
// (src/core).

#include "ellipse_collision/core/ellipse.h"
#include "rotating_separation.h"

namespace ellipse_collision::core::detail {

/// What the steps of one pair need besides the pair.
struct StepBounds {
  double approach_speed;  ///< V [m/s]
  double curvature;       ///< M [m/s^2]
  bool second_order;
  double graze;     ///< the grazing band [m]
  double tiny_gap;  ///< below it the witness direction is a's normal [m]
  // The turning direction's bound (turningRoot()):
  double centre_speed;    ///< V_p [m/s]
  double arc_curvature;   ///< |wa| |v_arc| [m/s^2]
  double sweep_a, sweep_b;  ///< K = R^2 / r - r of a and b, 0 for a circle [m]
  // The radii of a and b, R >= r, for K over the directions a step sweeps (sweptCurvature()).
  double big_a, small_a, big_b, small_b;
};

/// Where the separation was taken: what the second-order steps need of the poses at t.
struct StepContext {
  double centre_distance;      ///< |p(t)|, raised by its rounding [m]
  double margin_a, margin_b;   ///< the rounding of a's and b's angles at t [rad]
  double remaining;            ///< horizon - t [s]
};

/// The second-order step of a separation: the larger of the fixed direction's bound over all
/// directions and of the bounds over the angles a step sweeps (fixed and turning u), whose cap
/// starts at twice the step that the bounds at t alone would give and grows by 8 while it, not
/// the root, holds the step back.
double secondOrderStep(const StepBounds& k, const SeparationAlong& s, double value, double wa,
                       double wb, const StepContext& at);

/// omega^2 (R^2 / r - r): the worst curvature of the support function of `e` turning at `omega`.
inline double sweepCurvature(const Ellipse& e, double omega) {
  const double big = boundingRadius(e), small = inscribedRadius(e);
  return omega * omega * (big * (big / small) - small);
}

/// Whether `e` turning at `omega` changes its support function (not a circle, omega != 0).
inline bool turns(const Ellipse& e, double omega) {
  return omega != 0.0 && e.radius_x != e.radius_y;
}

}  // namespace ellipse_collision::core::detail
