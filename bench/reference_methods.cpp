#include "reference_methods.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/overlap.h"
#include "rotating_contact.h"

namespace ellipse_collision::core::bench {
namespace {

std::unique_ptr<fcl::CollisionObjectd> fclObject(const Ellipse& e) {
  auto shape =
      std::make_shared<fcl::Ellipsoidd>(e.radius_x, e.radius_y, std::min(e.radius_x, e.radius_y));
  fcl::Transform3d pose = fcl::Transform3d::Identity();
  pose.translation() = fcl::Vector3d(e.center.x(), e.center.y(), 0.0);
  pose.linear() = fcl::AngleAxisd(e.angle, fcl::Vector3d::UnitZ()).toRotationMatrix();
  return std::make_unique<fcl::CollisionObjectd>(shape, pose);
}

/// Quadratic-form matrix A of {x : (x - c)^T A (x - c) <= 1}.
Eigen::Matrix2d quadraticForm(const Ellipse& e) {
  const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(e.angle).toRotationMatrix();
  const Eigen::Vector2d inverse_squares(1.0 / (e.radius_x * e.radius_x),
                                        1.0 / (e.radius_y * e.radius_y));
  return rotation * inverse_squares.asDiagonal() * rotation.transpose();
}

// The demo's optimiser settings.
constexpr double kDifferenceStep = 1e-4;
constexpr double kLearningRate = 1e-2;
constexpr double kGradientTolerance = 1e-3;
constexpr int kMaxIterations = 100;

// ---- the secant method on the contact scale: firstContact()'s translation before the sum's entry
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
namespace secant {

constexpr int kMaxSecantSteps = 60;
constexpr int kMaxGoldenSteps = 90;
constexpr int kMaxBisections = 80;
// Relative error of contactScale() allowed for: ~1e-15 for round shapes, measured up to ~3e-13
// for thin ones near tangency. Differences of g below 4x this are noise.
constexpr double kScaleRounding = 2.5e-12;
// The first step is shrunk by this factor (as conservative advancement's).
constexpr double kStepShrink = 1.0 - 1e-9;

// In the frame of a's centre: a at the origin, b at p0 moving at w.
struct RelativePair {
  Ellipse a;
  Ellipse b;
  Eigen::Vector2d w;
};

double scaleAt(const RelativePair& p, double t) {
  Ellipse b = p.b;
  b.center += p.w * t;
  return contactScale(p.a, b);
}

FirstContact contactAt(double t) { return {true, t}; }

// First t in [lo, hi] with g(t) <= 1, given g(lo) > 1 and g(hi) <= 1.
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

}  // namespace secant

}  // namespace

FclEllipse::FclEllipse(const Ellipse& ellipse) : object_(fclObject(ellipse)) {}

bool fclCollide(const FclEllipse& a, const FclEllipse& b) {
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(a.object(), b.object(), request, result);
  return result.isCollision();
}

bool seedReadmeOverlap(const Ellipse& a, const Ellipse& b) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(
      quadraticForm(a).inverse(), quadraticForm(b).inverse());
  const Eigen::Array2d lambda = solver.eigenvalues().array();
  const Eigen::Array2d v_squared =
      (solver.eigenvectors().transpose() * (a.center - b.center)).array().square();
  const auto k = [&](double s) {
    return 1.0 - (v_squared * (s * (1.0 - s) / (1.0 + s * (lambda - 1.0)))).sum();
  };
  const auto gradient = [&](double s) { return (k(s + kDifferenceStep) - k(s)) / kDifferenceStep; };

  double s = 0.5;
  double slope = gradient(s);
  for (int i = 0; i < kMaxIterations && std::abs(slope) > kGradientTolerance; ++i) {
    // Kept inside (0, 1), where K is defined.
    s = std::clamp(s - kLearningRate * slope, kDifferenceStep, 1.0 - 2.0 * kDifferenceStep);
    slope = gradient(s);
  }
  return k(s) >= 0.0;
}

FirstContact secantFirstContact(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                                const Motion& motion_b, double horizon) {
  // The same canonical order as firstContact(), for the same symmetry (and the same work).
  const auto key = [](const Ellipse& e, const Motion& m) {
    return std::make_tuple(e.center.x(), e.center.y(), e.radius_x, e.radius_y, e.angle,
                           m.velocity.x(), m.velocity.y());
  };
  if (key(b, motion_b) < key(a, motion_a)) {
    return secantFirstContact(b, motion_b, a, motion_a, horizon);
  }
  if (overlap(a, b)) return {true, 0.0};
  if (!(horizon > 0.0)) return {};
  secant::RelativePair p{a, b, motion_b.velocity - motion_a.velocity};
  p.a.center = Eigen::Vector2d::Zero();
  p.b.center = b.center - a.center;
  FirstContact contact = secant::translationContact(p, horizon);
  // Time 0 is for pairs that overlap now (overlap() said apart).
  if (contact.contact && contact.time == 0.0) {
    contact.time = std::min(horizon, std::numeric_limits<double>::denorm_min());
  }
  return contact;
}

// ---- plain conservative advancement: rotating first contacts before the second-order steps ----
// Steps of D / V on the exact distance (Mirtich 1996; Zhang, Lee, Kim, Manocha 2006), V a bound on
// how fast the rims approach (doc/rotating_contact.md derives it): certified never late, but near a
// grazing pass the steps shrink with the gap (about sqrt(size / gap) of them), so the pair is
// reported in contact once the distance is within the grazing band, or at the cap.
namespace plain {

/// The first contact in [0, horizon] of `pair_at(t)` (a std::pair of ellipses at time t), whose
/// rims approach no faster than `approach_speed`; `inscribed_sum` = r_a + r_b sets the band.
template <class PairAt>
FirstContact advance(PairAt&& pair_at, double approach_speed, double inscribed_sum,
                     double horizon) {
  if (!(approach_speed > 0.0)) {
    const auto [a, b] = pair_at(0.0);
    if (distance(a, b).separated) return {};
    return {true, 0.0};
  }
  const double graze = detail::kGrazeDistance * inscribed_sum;
  double t = 0.0;
  for (int i = 0; i < kPlainAdvancementCap; ++i) {
    const auto [a, b] = pair_at(t);
    const Clearance c = distance(a, b);
    if (!c.separated) return {true, t};
    if (c.distance <= graze) return {true, t};  // within the band around tangency
    const double next = t + c.distance * detail::kStepShrink / approach_speed;
    if (next > horizon) {
      if (t == horizon) return {};
      t = horizon;
      continue;
    }
    if (!(next > t)) return {true, t};
    t = next;
  }
  return {true, t};  // the cap: contact claimed at the last certified-safe time
}

/// `advance()` counting the pairs asked for, apart at t = 0 (time 0 only for overlap now).
template <class PairAt>
FirstContact counted(const Ellipse& a, const Ellipse& b, PairAt&& pair_at, double approach_speed,
                     double horizon, int* distance_calls) {
  int calls = 0;
  if (distance_calls) *distance_calls = 0;
  if (overlap(a, b)) return {true, 0.0};
  if (!(horizon > 0.0)) return {};
  const FirstContact contact = advance(
      [&](double t) {
        ++calls;
        return pair_at(t);
      },
      approach_speed, inscribedRadius(a) + inscribedRadius(b), horizon);
  if (distance_calls) *distance_calls = calls;
  return detail::apartAtZero(contact, horizon);
}

double sweepSpeed(const Ellipse& e, double omega) {
  return std::fabs(omega) * (boundingRadius(e) - inscribedRadius(e));
}

}  // namespace plain

FirstContact plainAdvancementFirstContact(const Ellipse& a, const Motion& motion_a,
                                          const Ellipse& b, const Motion& motion_b, double horizon,
                                          int* distance_calls) {
  const Eigen::Vector2d w = motion_b.velocity - motion_a.velocity;
  const Eigen::Vector2d p0 = b.center - a.center;
  const double wa = motion_a.angular_velocity, wb = motion_b.angular_velocity;
  const double approach_speed =
      std::hypot(w.x(), w.y()) + plain::sweepSpeed(a, wa) + plain::sweepSpeed(b, wb);
  auto pair_at = [&](double t) {
    Ellipse at = a, bt = b;
    at.center = Eigen::Vector2d::Zero();
    at.angle = a.angle + wa * t;
    bt.center = p0 + w * t;
    bt.angle = b.angle + wb * t;
    return std::make_pair(at, bt);
  };
  return plain::counted(a, b, pair_at, approach_speed, horizon, distance_calls);
}

FirstContact plainAdvancementTwistContact(const Ellipse& link, const Twist& twist,
                                          const Ellipse& obstacle, const Motion& obstacle_motion,
                                          double horizon, int* distance_calls) {
  const Eigen::Vector2d link_velocity(twist.vx - twist.wz * link.center.y(),
                                      twist.vy + twist.wz * link.center.x());
  const double approach_speed =
      detail::largestCentreSpeed(obstacle_motion.velocity, link_velocity, twist.wz * horizon) +
      plain::sweepSpeed(link, twist.wz) +
      plain::sweepSpeed(obstacle, obstacle_motion.angular_velocity);
  auto pair_at = [&](double t) {
    return std::make_pair(linkAfter(link, twist, t), movedBy(obstacle, obstacle_motion, t));
  };
  return plain::counted(link, obstacle, pair_at, approach_speed, horizon, distance_calls);
}

FirstContact plainAdvancementSegmentContact(const Ellipse& link_in_moving,
                                            const SegmentMotion& motion, const Ellipse& obstacle,
                                            const Motion& obstacle_motion, int* distance_calls) {
  const double w = motion.yaw_rate;
  const double approach_speed = (motion.velocity - obstacle_motion.velocity).norm() +
                                std::fabs(w) * link_in_moving.center.norm() +
                                plain::sweepSpeed(link_in_moving, w) +
                                plain::sweepSpeed(obstacle, obstacle_motion.angular_velocity);
  auto pair_at = [&](double t) {
    return std::make_pair(
        placeAt(link_in_moving, motion.start + motion.velocity * t, motion.start_yaw + w * t),
        movedBy(obstacle, obstacle_motion, t));
  };
  return plain::counted(placeAt(link_in_moving, motion.start, motion.start_yaw), obstacle, pair_at,
                        approach_speed, motion.duration, distance_calls);
}

}  // namespace ellipse_collision::core::bench
