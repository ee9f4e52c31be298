#pragma once

#include <limits>
#include <utility>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"

namespace ellipse_collision::core::detail {

// Conservative advancement (Mirtich 1996; Zhang, Lee, Kim, Manocha 2006) on the exact distance,
// for motions with rotation: firstContact()'s turning pairs and ~check_path's links turning about
// the moving frame's origin (path_motion.cpp).
// Why it cannot step past a contact: by the support-function dual (distance.h)
//   D(t) = max over unit u of  u . p(t) - h_a(u, t) - h_b(u, t)   (clipped at 0),
// and for an ellipse of semi-axes R >= r turning at w about its centre, |dh/dt| = |w| |dh/dphi|
// <= |w| (R - r) (the largest distance from the centre to a normal line of the ellipse is R - r),
// while |d(u . p)/dt| <= |v_b - v_a|. A maximum of functions with that Lipschitz constant has it
// too, so |D'(t)| <= V, the caller's bound on how fast the rims can approach (for firstContact:
// |v_b - v_a| + |w_a| (R_a - r_a) + |w_b| (R_b - r_b); a centre moving on an arc adds its speed),
// and no contact happens in [t, t + D(t) / V). Stepping by slightly less than D / V therefore
// never passes the first contact. When D drops below kGrazeDistance of r_a + r_b the contact scale
// is within kGrazeDistance of 1 (K contains the disc of radius r_a + r_b, so t* <= 1 + D / (r_a +
// r_b)): inside the 1e-9 band where either answer is accepted, and the pair is reported in contact
// at that certified-safe time. The step count is capped (kMaxAdvancements); at the cap the pair is
// reported in contact at the last certified-safe time, never clear. Near grazing the steps shrink
// with the distance (about sqrt(size / gap) of them), so a turning pair that passes within ~1e-8
// relative of touching can reach the cap and is then reported, conservatively, in contact.
inline constexpr int kMaxAdvancements = 20000;  // ~40 ms of distance() calls at most (2 us each)
inline constexpr double kGrazeDistance = 5e-10;
inline constexpr double kStepShrink = 1.0 - 1e-9;

/// The first contact in [0, horizon] of the pair `pair_at(t)` (a std::pair of ellipses at time
/// t), whose rims approach no faster than `approach_speed`; `inscribed_sum` = r_a + r_b sets the
/// grazing band. Never late; clear only when certified.
/// With `until` < horizon the steps stop once the next one would pass `until`: the answer is the
/// horizon's answer when that is a contact at or before `until`, and no contact otherwise (the
/// same steps, so the same time: a caller that needs only contacts up to `until` loses nothing).
template <class PairAt>
FirstContact advanceConservatively(PairAt&& pair_at, double approach_speed, double inscribed_sum,
                                   double horizon,
                                   double until = std::numeric_limits<double>::infinity()) {
  if (!(approach_speed > 0.0)) {
    const auto [a, b] = pair_at(0.0);
    if (distance(a, b).separated) return {};
    return {true, 0.0};
  }
  const double graze = kGrazeDistance * inscribed_sum;
  double t = 0.0;
  for (int i = 0; i < kMaxAdvancements; ++i) {
    const auto [a, b] = pair_at(t);
    const Clearance c = distance(a, b);
    if (!c.separated) return {true, t};
    if (c.distance <= graze) return {true, t};  // within the band around tangency
    // Shrunk a little against the ~1e-16 relative rounding of the distance and of t + step.
    const double next = t + c.distance * kStepShrink / approach_speed;
    if (next > until && until < horizon) return {};  // any contact comes after `until`
    if (next > horizon) {
      // [t, horizon] is certified clear unless the horizon itself touches: the last interval is
      // shortened to end exactly at the horizon and checked there.
      if (t == horizon) return {};
      t = horizon;
      continue;
    }
    if (!(next > t)) return {true, t};  // step below the resolution of t: certified safe here
    t = next;
  }
  return {true, t};  // iteration cap: no contact before t is certified, claim contact at t
}

}  // namespace ellipse_collision::core::detail
