#include "ellipse_collision/core/first_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/eigenvalue_test.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/overlap.h"
#include "conservative_advancement.h"

namespace ellipse_collision::core {
namespace {

// ---- translation ----------------------------------------------------------------------------
// With both shapes fixed, b - a is the centred Minkowski sum K = A + B, and the pair overlaps at t
// iff the gauge of K at the relative offset p(t) = p0 + w t is <= 1 (Perram & Wertheim 1985;
// Gilitschenski & Hanebeck 2012: this gauge is the contact scale t*). A gauge is convex and p(t)
// is affine, so g(t) = contactScale(t) is convex in t. For a convex g the line through two samples
// t_{k-1} < t_k lies below g beyond t_k, so the secant step from two samples left of the first
// root lands left of it again: the iteration approaches the root monotonically from the left
// (never late), superlinearly for a transversal crossing. It starts where the bounding circles
// first meet (no contact before) with one step the gauge's Lipschitz bound makes safe. A rise of g
// beyond its rounding, or a secant root beyond the horizon, proves g > 1 on the rest of the
// horizon (clear). Where the secant stalls (grazing: linear convergence; or differences within
// rounding) a golden-section search for the minimum of the convex g and a bisection of the first
// crossing decide, neither needing a slope.
constexpr int kMaxSecantSteps = 60;
constexpr int kMaxGoldenSteps = 90;
constexpr int kMaxBisections = 80;
// Relative error of contactScale() we allow for: ~1e-15 for round shapes, measured up to ~3e-13 for
// thin ones near tangency (the tests only claim 1e-9). Differences of g below 4x this are noise.
constexpr double kScaleRounding = 2.5e-12;

// ---- rotation: conservative advancement (conservative_advancement.h) ----------------------
// The translation case's first step is shrunk by the same factor.
using detail::kStepShrink;

// Everything in the frame of a's centre, so that centres 1e6 m out lose no precision.
struct RelativePair {
  Ellipse a;  // centred at the origin
  Ellipse b;  // centred at p0
  Eigen::Vector2d w;  // v_b - v_a [m/s]
  double wa, wb;      // angular velocities [rad/s]

  Ellipse aAt(double t) const {
    Ellipse e = a;
    e.angle = a.angle + wa * t;
    return e;
  }
  Ellipse bAt(double t) const {
    Ellipse e = b;
    e.center = b.center + w * t;
    e.angle = b.angle + wb * t;
    return e;
  }
};

double scaleAt(const RelativePair& p, double t) { return contactScale(p.a, p.bAt(t)); }

FirstContact contactAt(double t) { return {true, t}; }

// First t in [lo, hi] with g(t) <= 1, given g(lo) > 1 and g(hi) <= 1; returns the right end of the
// final bracket (g <= 1 there, within kScaleRounding-level of the crossing).
double bisectCrossing(const RelativePair& p, double lo, double hi) {
  for (int i = 0; i < kMaxBisections && hi - lo > 0.0; ++i) {
    const double mid = lo + 0.5 * (hi - lo);
    if (mid <= lo || mid >= hi) break;
    (scaleAt(p, mid) <= 1.0 ? hi : lo) = mid;
  }
  return hi;
}

FirstContact translationContact(const RelativePair& p, double horizon) {
  const double speed = std::hypot(p.w.x(), p.w.y());  // hypot: no underflow for tiny w
  if (!(speed > 0.0)) return {};  // same velocity: the t = 0 answer holds throughout
  // Bounding circles first: before the relative centre comes within R_a + R_b (enlarged against
  // rounding) no contact is possible, and a path that never does is clear without any gauge.
  // Distances along and across the path are formed from p0 directly (absolute rounding ~eps |p0|,
  // covered by `slack`).
  const Eigen::Vector2d& p0 = p.b.center;
  const double slack = 4e-15 * p0.norm();
  const double outer = (boundingRadius(p.a) + boundingRadius(p.b)) * (1.0 + 1e-9) + slack;
  // The unit direction of w from w scaled by a power of two (exact), so that a tiny or subnormal
  // relative velocity keeps its full precision.
  const double w_max = std::max(std::fabs(p.w.x()), std::fabs(p.w.y()));
  const Eigen::Vector2d dir = (p.w * std::ldexp(1.0, -std::ilogb(w_max))).normalized();
  const double across = std::fabs(p0.x() * dir.y() - p0.y() * dir.x());
  if (across > outer) return {};  // the line stays outside the circle of radius `outer`
  const double along = -p0.dot(dir);  // [m] to the point of the line nearest the origin
  const double half_chord = std::sqrt((outer - across) * (outer + across));
  if ((along + half_chord + slack) / speed < 0.0) return {};  // moving away
  const double enter = (along - half_chord - slack) / speed;  // [s], certified early
  if (enter > horizon) return {};
  double t_prev = std::max(0.0, enter);
  double g_prev = scaleAt(p, t_prev);
  if (g_prev <= 1.0) return contactAt(t_prev);  // at t = 0: overlap() and contactScale() disagree by rounding
  // First step: the gauge of K is Lipschitz with constant 1 / (r_a + r_b) (K contains the disc of
  // that radius), so g'(t) >= -speed / (r_a + r_b) and this step cannot pass the root.
  const double inradius = inscribedRadius(p.a) + inscribedRadius(p.b);
  double t = t_prev + (g_prev - 1.0) * (inradius / speed) * kStepShrink;
  if (t > horizon) return {};
  double g = scaleAt(p, t);
  if (g <= 1.0) return contactAt(t);
  for (int step = 0; step < kMaxSecantSteps; ++step) {
    // Differences within the rounding of contactScale() prove nothing: then the search for the
    // minimum below decides (it needs no slope).
    const double noise = 4.0 * kScaleRounding * std::max(g, g_prev);
    if (g - g_prev > noise) return {};  // g increasing from t on (convex): it stays > 1
    if (g_prev - g <= noise) break;
    // The secant of the true g through these two samples, each known to within `error`, is
    // steepest when the fall is `error` larger at both ends, and its root is then nearest: a
    // step to it stays left of the root even where g is nearly straight and the samples close
    // (the plain secant overshot by 1.7e-6 of the time there: fuzzer finding).
    const double error = kScaleRounding * std::max(g, g_prev);
    const double fall = g_prev - g;
    const double slope = -(fall + 2.0 * error) / (t - t_prev);
    const double advance = std::max(0.0, g - 1.0 - error) / -slope;
    const double next = t + advance;
    if (next > horizon) return {};  // even the steepest secant (below g) stays > 1 to the horizon
    if (advance <= 1e-15 * horizon || g - 1.0 <= kScaleRounding * g) return contactAt(next);
    const double g_next = scaleAt(p, next);
    if (g_next <= 1.0) return contactAt(next);  // landed on the root within rounding
    t_prev = t, g_prev = g;
    t = next, g = g_next;
  }
  // Grazing: golden section for the minimum of the convex g on [t, horizon]; all t' < t are
  // certified clear already.
  constexpr double kInvPhi = 0.6180339887498949;
  double lo = t, hi = horizon;
  double x1 = hi - kInvPhi * (hi - lo), x2 = lo + kInvPhi * (hi - lo);
  double g1 = scaleAt(p, x1), g2 = scaleAt(p, x2);
  for (int i = 0; i < kMaxGoldenSteps; ++i) {
    if (g1 <= 1.0) return contactAt(bisectCrossing(p, lo, x1));
    if (g2 <= 1.0) return contactAt(bisectCrossing(p, lo, x2));
    if (g1 <= g2) {
      hi = x2, x2 = x1, g2 = g1;
      x1 = hi - kInvPhi * (hi - lo);
      g1 = scaleAt(p, x1);
    } else {
      lo = x1, x1 = x2, g1 = g2;
      x2 = lo + kInvPhi * (hi - lo);
      g2 = scaleAt(p, x2);
    }
    if (!(hi - lo > 1e-15 * horizon)) break;
  }
  if (g1 <= 1.0) return contactAt(bisectCrossing(p, t, x1));
  if (g2 <= 1.0) return contactAt(bisectCrossing(p, t, x2));
  const double g_end = scaleAt(p, horizon);
  if (g_end <= 1.0) return contactAt(bisectCrossing(p, t, horizon));
  return {};
}

FirstContact rotationContact(const RelativePair& p, double horizon) {
  // Rounding of R - r is harmless: it is exact (Sterbenz) when r >= R / 2, and tiny against R.
  const double approach_speed =
      std::hypot(p.w.x(), p.w.y()) + std::fabs(p.wa) * (boundingRadius(p.a) - inscribedRadius(p.a)) +
      std::fabs(p.wb) * (boundingRadius(p.b) - inscribedRadius(p.b));
  if (!(approach_speed > 0.0)) return {};
  return detail::advanceConservatively(
      [&p](double t) { return std::make_pair(p.aAt(t), p.bAt(t)); }, approach_speed,
      inscribedRadius(p.a) + inscribedRadius(p.b), horizon);
}

// A total order on (ellipse, motion): the pair is always processed in this order, which makes
// firstContact exactly symmetric.
auto orderKey(const Ellipse& e, const Motion& m) {
  return std::make_tuple(e.center.x(), e.center.y(), e.radius_x, e.radius_y, e.angle,
                         m.velocity.x(), m.velocity.y(), m.angular_velocity);
}

std::string pathReason(const Ellipse& e, const Motion& m, double horizon) {
  const char* const names[2] = {"center.x", "center.y"};
  for (int i = 0; i < 2; ++i) {
    const double end = e.center[i] + m.velocity[i] * horizon;
    if (!coordinateOk(end)) {
      return std::string(names[i]) + " at the horizon = " + formatNumber(end) + " is outside [" +
             formatNumber(-kMaxCoordinate) + ", " + formatNumber(kMaxCoordinate) + "] m";
    }
  }
  return {};
}

}  // namespace

std::string invalidVelocityReason(const Motion& m, double horizon,
                                  const VelocityFieldNames& names) {
  const char* const components[2] = {names.x, names.y};
  for (int i = 0; i < 2; ++i) {
    const double v = m.velocity[i];
    if (!std::isfinite(v)) {
      return std::string(components[i]) + " = " + formatNumber(v) + " must be finite";
    }
    if (std::fabs(v) > kMaxSpeed) {
      return std::string(components[i]) + " = " + formatNumber(v) + " is outside [" +
             formatNumber(-kMaxSpeed) + ", " + formatNumber(kMaxSpeed) + "] m/s";
    }
  }
  const double w = m.angular_velocity;
  // Called for every obstacle a check or the gate looks at: no string unless there is a problem.
  const char* const angular = names.angular;
  if (!std::isfinite(w)) return angular + (" = " + formatNumber(w)) + " must be finite";
  if (std::fabs(w) > kMaxAngularVelocity) {
    return angular + (" = " + formatNumber(w)) + " is outside [" +
           formatNumber(-kMaxAngularVelocity) + ", " + formatNumber(kMaxAngularVelocity) +
           "] rad/s";
  }
  if (std::fabs(w) * horizon > kMaxTurn) {
    return angular + (" = " + formatNumber(w)) + " turns more than " + formatNumber(kMaxTurn) +
           " rad within horizon = " + formatNumber(horizon) + " s";
  }
  return {};
}

std::string invalidMotionReason(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                                const Motion& motion_b, double horizon) {
  if (std::string r = invalidReason(a); !r.empty()) return "ellipse 1: " + r;
  if (std::string r = invalidReason(b); !r.empty()) return "ellipse 2: " + r;
  if (!std::isfinite(horizon)) return "horizon = " + formatNumber(horizon) + " must be finite";
  if (horizon < 0.0) return "horizon = " + formatNumber(horizon) + " must be >= 0";
  if (std::string r = invalidVelocityReason(motion_a, horizon); !r.empty()) {
    return "motion 1: " + r;
  }
  if (std::string r = invalidVelocityReason(motion_b, horizon); !r.empty()) {
    return "motion 2: " + r;
  }
  if (std::string r = pathReason(a, motion_a, horizon); !r.empty()) return "motion 1: " + r;
  if (std::string r = pathReason(b, motion_b, horizon); !r.empty()) return "motion 2: " + r;
  return {};
}

std::string invalidMotionReason(const Ellipse& e, const Motion& motion, double horizon) {
  if (std::string r = invalidReason(e); !r.empty()) return r;
  if (std::string r = invalidVelocityReason(motion, horizon); !r.empty()) return r;
  return pathReason(e, motion, horizon);
}

FirstContact firstContact(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                          const Motion& motion_b, double horizon) {
  if (orderKey(b, motion_b) < orderKey(a, motion_a)) {
    return firstContact(b, motion_b, a, motion_a, horizon);
  }
  if (overlap(a, b)) return contactAt(0.0);
  if (!(horizon > 0.0)) return {};
  RelativePair p{a, b, motion_b.velocity - motion_a.velocity, motion_a.angular_velocity,
                 motion_b.angular_velocity};
  p.a.center = Eigen::Vector2d::Zero();
  p.b.center = b.center - a.center;
  // A spinning circle sweeps nothing: such pairs translate, and the exact method applies.
  const bool a_turns = p.wa != 0.0 && p.a.radius_x != p.a.radius_y;
  const bool b_turns = p.wb != 0.0 && p.b.radius_x != p.b.radius_y;
  FirstContact contact;
  if (!a_turns && !b_turns) {
    p.wa = p.wb = 0.0;
    contact = translationContact(p, horizon);
  } else {
    contact = rotationContact(p, horizon);
  }
  // overlap() said they are apart at t = 0; a pair whose contact scale there is within rounding
  // of 1 can still be found touching "at 0" by the gauge. Time 0 means overlapping now (the
  // documented rule), so such a contact is reported at the first time after 0 (fuzzer finding).
  if (contact.contact && contact.time == 0.0) {
    contact.time = std::min(horizon, std::numeric_limits<double>::denorm_min());
  }
  return contact;
}

}  // namespace ellipse_collision::core
