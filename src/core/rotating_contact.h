#pragma once

// The first contact of a pair that turns (doc/rotating_contact.md). Internal to the core
// (src/core).

#include <Eigen/Core>
#include <algorithm>
#include <limits>

#include "ellipse_collision/core/first_contact.h"
#include "rotating_pair.h"

namespace ellipse_collision::core::detail {

/// Resolution of the first contact of a rotating pair, relative to the horizon: the answer is
/// never later than the true first contact and, where the pair overlaps within this of it, no more
/// than this earlier.
inline constexpr double kRotationResolution = 2.5e-10;
/// Safety cap on the steps; the tests and the benchmark count the pairs that reach it (none, up
/// to axis ratios of 1e8 for two needles turning at different rates and 1e14 for a needle
/// against a disc). A pair that reaches it is claimed in contact where the steps stopped, never
/// late.
inline constexpr int kMaxRotationSteps = 20000;
/// A pair within this distance, relative to r_a + r_b, at a time where the steps cannot go on is
/// at a tangency: reported in contact there (doc/rotating_contact.md).
inline constexpr double kGrazeDistance = 5e-10;
/// Steps are shrunk by this against the ~1e-16 relative rounding of the distance and of t + step.
inline constexpr double kStepShrink = 1.0 - 1e-9;

/// What one call did, for the tests and the benchmark.
struct RotationWork {
  int distance_calls{0};
  bool capped{false};
};

/// The first contact in [0, horizon] of a rotating pair apart at t = 0 (doc/rotating_contact.md):
/// never late, at most kRotationResolution * horizon early where the pair overlaps within that of
/// it, and in contact at a tangency within the kGrazeDistance band. `work`, when given, receives
/// the work done. With `until` < horizon the steps stop once the next one would pass `until`: the
/// answer is the horizon's answer when that is a contact at or before `until`, and no contact
/// otherwise (the same steps, so the same time: a caller that needs only contacts up to `until`
/// loses nothing).
FirstContact rotatingContact(const RotatingPair& pair, double horizon, RotationWork* work = nullptr,
                             double until = std::numeric_limits<double>::infinity());

/// Largest |w - R(s) v| [m/s] over the turns s between 0 and `turn` [rad]: a bound on the speed of
/// a centre whose velocity is w plus v turning (doc/rotating_contact.md, first order).
double largestCentreSpeed(const Eigen::Vector2d& w, const Eigen::Vector2d& v, double turn);

/// Time 0 means overlapping now (firstContact()'s rule): a contact found at 0 for a pair that
/// overlap() calls apart is reported at the first time after 0.
inline FirstContact apartAtZero(FirstContact contact, double horizon) {
  if (contact.contact && contact.time == 0.0) {
    contact.time = std::min(horizon, std::numeric_limits<double>::denorm_min());
  }
  return contact;
}

}  // namespace ellipse_collision::core::detail
