#include "rotating_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "rotating_separation.h"
#include "rotating_step_bounds.h"

namespace ellipse_collision::core::detail {

// Conservative advancement (Mirtich 1996; Zhang, Lee, Kim, Manocha 2006) on the exact distance,
// each step the larger of D / V and the roots of second-order bounds of the separation along a
// fixed and a turning direction; the derivation, the rounding and the stopping rule are in
// doc/rotating_contact.md.
namespace {

/// The steps of rotatingContact(); kArc: the pair has an arc (RotatingPair::hasArc()), so that
/// firstContact()'s pairs run without its branches.
template <bool kArc>
FirstContact advance(const RotatingPair& p, const StepBounds& k, double horizon, double until,
                     RotationWork& done) {
  const auto bAt = [&p](double t) {
    Ellipse e = p.b;
    e.center = p.b.center + p.w * t;
    if constexpr (kArc) e.center -= p.arcAt(t);
    e.angle = p.b.angle + p.wb * t;
    return e;
  };
  const auto centreVelocity = [&p](double t) {
    Eigen::Vector2d v = p.w;
    if constexpr (kArc) v -= p.arcVelocityAt(t);
    return v;
  };
  // |p(t)| from b's double pose at t, raised by what rounding the pose left out.
  const auto centreDistance = [&p](const Ellipse& b, double t) {
    double moved = p.b.center.norm() + p.w.norm() * t;
    if constexpr (kArc) moved += p.a_arc_velocity.norm() * t;
    return b.center.norm() + 4.0 * std::numeric_limits<double>::epsilon() * moved;
  };
  // What the second-order steps need of the poses at t.
  const auto contextAt = [&](const Ellipse& a, const Ellipse& b, double t) {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    return StepContext{centreDistance(b, t), 8.0 * kEps * (1.0 + std::fabs(a.angle)),
                       8.0 * kEps * (1.0 + std::fabs(b.angle)), horizon - t};
  };
  const double resolution = kRotationResolution * horizon;
  double t = 0.0;
  for (int i = 0; i < kMaxRotationSteps; ++i) {
    const Ellipse a = p.aAt(t), b = bAt(t);
    const Clearance c = distance(a, b);
    ++done.distance_calls;
    if (!c.separated) return {true, t};
    // Plain steps cannot resolve a grazing band; they stop there.
    if (!k.second_order && c.distance <= k.graze) return {true, t};
    double step = c.distance * kStepShrink / k.approach_speed;
    // A first-order step past `until` or the horizon decides as any longer one would: the gate's
    // search stops most pairs so, and the second order is not needed there.
    const bool decided = step >= resolution && t + step > std::min(until, horizon);
    // The direction between the witness points, or for a tiny gap a's normal at its own.
    Eigen::Vector2d direction = c.point_b - c.point_a;
    const double gap = direction.norm();
    bool blurred = false;  // the separation's rounding allowance costs much of it
    Eigen::Vector2d last_direction;
    if (k.second_order && !decided &&
        (gap > k.tiny_gap ? (direction /= gap, true) : rimNormal(a, c.point_a, &direction))) {
      const Eigen::Vector2d centre_velocity = centreVelocity(t);
      Separation s = bestSeparation(a, b, centre_velocity, p.wa, p.wb, direction);
      // A needle's witness point can lie anywhere along its flat side within rounding of the
      // distance, and the direction between the points then says nothing (one 1.4e14 long was
      // 3e5 m off along it, the separation along it -2.6e7 m for a gap of 3e-8 m): the rim
      // normals at the witness points, one of which is well placed, are tried too.
      if (!(s.best.value - s.best.rounding > 0.5 * c.distance)) {
        Eigen::Vector2d normal;
        for (int side = 0; side < 2; ++side) {
          if (!(side == 0 ? rimNormal(a, c.point_a, &normal)
                          : (rimNormal(b, c.point_b, &normal) && (normal = -normal, true)))) {
            continue;
          }
          const Separation other = bestSeparation(a, b, centre_velocity, p.wa, p.wb, normal);
          if (other.best.value - other.best.rounding > s.best.value - s.best.rounding) s = other;
        }
      }
      const double value = s.best.value - s.best.rounding;
      blurred = !(value > kPreciseBelow * s.best.rounding);
      last_direction = s.last_direction;
      if (value > 0.0) {
        step = std::max(step, secondOrderStep(k, s.best, value, p.wa, p.wb, contextAt(a, b, t)));
      }
    }
    if (step < resolution) {
      const double probe = std::min(t + resolution, horizon);
      if (overlap(p.aAt(probe), bAt(probe))) return {true, t};
      // The long double separation, where the double one's rounding holds the steps back.
      if (blurred) {
        const SeparationAlong precise =
            preciseSeparation(p, t, centreVelocity(t), last_direction, k.sweep_a >= k.sweep_b);
        if (precise.value > 0.0) {
          step = std::max(step, secondOrderStep(k, precise, precise.value, p.wa, p.wb,
                                                contextAt(a, b, t)));
        }
      }
      if (step < resolution && c.distance <= k.graze) return {true, t};  // a tangency in the band
    }
    const double next = t + step;
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
  done.capped = true;
  return {true, t};  // safety cap: no contact before t is certified, claim contact at t
}

}  // namespace

FirstContact rotatingContact(const RotatingPair& p, double horizon, RotationWork* work,
                             double until) {
  RotationWork local;
  RotationWork& done = work ? *work : local;
  done = {};
  StepBounds k;
  // Rounding of R - r is harmless: it is exact (Sterbenz) when r >= R / 2, and tiny against R.
  k.centre_speed = p.hasArc() ? largestCentreSpeed(p.w, p.a_arc_velocity, p.wa * horizon)
                              : std::hypot(p.w.x(), p.w.y());
  k.approach_speed = k.centre_speed +
                     std::fabs(p.wa) * (boundingRadius(p.a) - inscribedRadius(p.a)) +
                     std::fabs(p.wb) * (boundingRadius(p.b) - inscribedRadius(p.b));
  if (!(k.approach_speed > 0.0)) return {};
  k.arc_curvature = p.hasArc() ? std::fabs(p.wa) * p.a_arc_velocity.norm() : 0.0;
  k.curvature = sweepCurvature(p.a, p.wa) + sweepCurvature(p.b, p.wb) + k.arc_curvature;
  // A curvature bound below the normal range (an angular velocity whose square underflows) or
  // overflowed is not trusted: then the steps are the plain ones. A pair with no turn at all
  // (spinning circles, no arc) has f linear in t: its curvature 0 is exact.
  const bool linear = !turns(p.a, p.wa) && !turns(p.b, p.wb) && !p.hasArc();
  k.second_order = linear || (k.curvature >= std::numeric_limits<double>::min() &&
                              k.curvature <= std::numeric_limits<double>::max());
  k.graze = kGrazeDistance * (inscribedRadius(p.a) + inscribedRadius(p.b));
  k.tiny_gap = kWitnessGap * (boundingRadius(p.a) + boundingRadius(p.b));
  k.sweep_a = sweepCurvature(p.a, 1.0);
  k.sweep_b = sweepCurvature(p.b, 1.0);
  k.big_a = boundingRadius(p.a), k.small_a = inscribedRadius(p.a);
  k.big_b = boundingRadius(p.b), k.small_b = inscribedRadius(p.b);
  return p.hasArc() ? advance<true>(p, k, horizon, until, done)
                    : advance<false>(p, k, horizon, until, done);
}

}  // namespace ellipse_collision::core::detail
