#include "grazing_passes.h"

#include <quadmath.h>

#include <cmath>

namespace ellipse_collision::core::test {
namespace {

using quad = __float128;
using ellipse_collision::test::RandomSource;
constexpr double kPi = 3.14159265358979323846;

Ellipse eccentric(RandomSource& rng, double major, double lo_ratio, double hi_ratio) {
  return {{0.0, 0.0}, major, major / rng.logUniform(lo_ratio, hi_ratio), rng.uniform(-kPi, kPi)};
}

Motion obstacleMotion(RandomSource& rng) {
  return {{rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)},
          rng.coin() ? rng.uniform(-1.0, 1.0) : 0.0};
}

/// The centre that an ellipse shaped like `b_at_t` needs at time t to touch `a_at_t` from the unit
/// direction `n`: a's centre plus n (h_a(n) + h_b(n)), h the support function.
Eigen::Vector2d touchingCentre(const Ellipse& a_at_t, const Ellipse& b_at_t,
                               const Eigen::Vector2d& n) {
  const auto support = [&n](const Ellipse& e) {
    const double c = std::cos(e.angle), s = std::sin(e.angle);
    return std::hypot(e.radius_x * (c * n.x() + s * n.y()), e.radius_y * (c * n.y() - s * n.x()));
  };
  return a_at_t.center + n * (support(a_at_t) + support(b_at_t));
}

/// A unit across the relative velocity `relative`, to either side.
Eigen::Vector2d acrossVelocity(RandomSource& rng, const Eigen::Vector2d& relative) {
  return Eigen::Vector2d(-relative.y(), relative.x()).normalized() * (rng.coin() ? 1.0 : -1.0);
}

/// Moves `out->b` (moving by `out->motion_b`) so that it touches `out->a` (moving by `motion_a`)
/// at t_pass from the unit direction `n`.
void placeTouching(const OracleRigidMotion& motion_a, double t_pass, const Eigen::Vector2d& n,
                   TurningPass* out) {
  const Motion& mb = out->motion_b;
  Ellipse b_then = out->b;
  b_then.angle += mb.angular_velocity * t_pass;
  out->b.center =
      touchingCentre(oraclePoseAt(out->a, motion_a, t_pass), b_then, n) - mb.velocity * t_pass;
}

/// Places `out->b` against `out->a` (moving by `motion_a`) at 0.3..0.7 of the horizon, from
/// across their relative velocity there, and makes the pass pass at `target`.
bool placeAndScale(RandomSource& rng, const OracleRigidMotion& motion_a, double target,
                   TurningPass* out) {
  const double t_pass = rng.uniform(0.3, 0.7) * out->horizon;
  const Motion& mb = out->motion_b;
  placeTouching(motion_a, t_pass,
                acrossVelocity(rng, mb.velocity - oracleVelocityAt(motion_a, t_pass)), out);
  out->pass = oracleGrazingPass(out->a, motion_a, out->b, oracleMotionOf(out->b, mb),
                                out->horizon, target);
  return out->pass.found;
}

std::string obstacleText(const TurningPass& p) {
  return exactNumbers({p.b.center.x(), p.b.center.y(), p.b.radius_x, p.b.radius_y, p.b.angle,
                       p.motion_b.velocity.x(), p.motion_b.velocity.y(),
                       p.motion_b.angular_velocity, p.horizon});
}

std::string linkText(const Ellipse& e) {
  return exactNumbers({e.center.x(), e.center.y(), e.radius_x, e.radius_y, e.angle});
}

/// The numbers of a pass of two ellipses that translate and turn about their centres.
std::string motionPassText(const TurningPass& p) {
  return "a " + linkText(p.a) + " moving " +
         exactNumbers({p.motion_a.velocity.x(), p.motion_a.velocity.y(),
                       p.motion_a.angular_velocity}) +
         "; b " + obstacleText(p);
}

/// A link offset 0.2..1.5 m from its frame's origin, major radius 0.1..1 m.
Ellipse offsetLink(RandomSource& rng) {
  const double offset = rng.uniform(0.2, 1.5), at = rng.uniform(-kPi, kPi);
  Ellipse link = eccentric(rng, rng.logUniform(0.1, 1.0), 3.0, 30.0);
  link.center = {offset * std::cos(at), offset * std::sin(at)};
  return link;
}

}  // namespace

OracleRigidMotion oracleTwistMotion(const Ellipse& link, const Twist& twist) {
  OracleRigidMotion m;
  m.x = link.center.x(), m.y = link.center.y(), m.angle = link.angle;
  m.ux = static_cast<quad>(twist.vx) - static_cast<quad>(twist.wz) * link.center.y();
  m.uy = static_cast<quad>(twist.vy) + static_cast<quad>(twist.wz) * link.center.x();
  m.turn_rate = twist.wz;
  return m;
}

OracleRigidMotion oracleSegmentMotion(const Ellipse& link_in_moving, const SegmentMotion& segment) {
  const quad c = cosq(segment.start_yaw), s = sinq(segment.start_yaw);
  const quad rx = c * link_in_moving.center.x() - s * link_in_moving.center.y();
  const quad ry = s * link_in_moving.center.x() + c * link_in_moving.center.y();
  OracleRigidMotion m;
  m.x = segment.start.x() + rx, m.y = segment.start.y() + ry;
  m.angle = static_cast<quad>(link_in_moving.angle) + segment.start_yaw;
  m.vx = segment.velocity.x(), m.vy = segment.velocity.y();
  m.ux = -segment.yaw_rate * ry, m.uy = segment.yaw_rate * rx;
  m.turn_rate = segment.yaw_rate;
  return m;
}

bool drawMotionPass(RandomSource& rng, double target, TurningPass* out) {
  TurningPass& p = *out;
  p = {};
  p.a = eccentric(rng, rng.logUniform(0.1, 1.0), 3.0, 30.0);
  const double phi = rng.uniform(-kPi, kPi), range = rng.uniform(0.0, 100.0);
  p.a.center = {range * std::cos(phi), range * std::sin(phi)};
  p.b = eccentric(rng, rng.logUniform(0.05, 1.0), 1.0, 20.0);
  const double heading = rng.uniform(-kPi, kPi), speed = rng.uniform(0.0, 1.0);
  p.motion_a = {{speed * std::cos(heading), speed * std::sin(heading)},
                (rng.coin() ? 1.0 : -1.0) * rng.uniform(0.4, 3.0)};
  p.motion_b = obstacleMotion(rng);
  p.motion_b.velocity += p.motion_a.velocity;
  p.horizon = 1.5;
  if (!placeAndScale(rng, oracleMotionOf(p.a, p.motion_a), target, out)) return false;
  p.text = motionPassText(p);
  return true;
}

bool drawTwistPass(RandomSource& rng, double target, TurningPass* out) {
  TurningPass& p = *out;
  p = {};
  p.a = offsetLink(rng);
  p.twist = {rng.uniform(-1.0, 1.0), rng.uniform(-0.5, 0.5),
             (rng.coin() ? 1.0 : -1.0) * rng.uniform(0.4, 1.5)};
  p.b = eccentric(rng, rng.logUniform(0.05, 1.0), 1.0, 20.0);
  p.motion_b = obstacleMotion(rng);
  p.horizon = 1.5;
  if (!placeAndScale(rng, oracleTwistMotion(p.a, p.twist), target, out)) return false;
  p.text = "link " + linkText(p.a) + " twist " +
           exactNumbers({p.twist.vx, p.twist.vy, p.twist.wz}) + "; obstacle " + obstacleText(p);
  return true;
}

bool drawSegmentPass(RandomSource& rng, double target, TurningPass* out) {
  TurningPass& p = *out;
  p = {};
  p.a = offsetLink(rng);
  const PathPose from{rng.uniform(-100.0, 100.0), rng.uniform(-100.0, 100.0),
                      rng.uniform(-kPi, kPi), 0.0};
  const PathPose to{from.x + rng.uniform(-2.0, 2.0), from.y + rng.uniform(-2.0, 2.0),
                    from.yaw + (rng.coin() ? 1.0 : -1.0) * rng.uniform(0.4, 3.0), 0.0};
  p.segment = segmentMotion(from, to, 1.0);
  p.b = eccentric(rng, rng.logUniform(0.05, 1.0), 1.0, 20.0);
  p.motion_b = obstacleMotion(rng);
  p.horizon = p.segment.duration;
  if (!placeAndScale(rng, oracleSegmentMotion(p.a, p.segment), target, out)) return false;
  p.text = "link " + linkText(p.a) + " from " + exactNumbers({from.x, from.y, from.yaw}) +
           " to " + exactNumbers({to.x, to.y, to.yaw}) + "; obstacle " + obstacleText(p);
  return true;
}

double placeNeedlePair(RandomSource& rng, double ratio, NeedleContact contact, TurningPass* out) {
  TurningPass& p = *out;
  p = {};
  const auto needle = [&rng, ratio](double major) {
    const bool x_major = rng.coin();
    return Ellipse{{0.0, 0.0}, x_major ? major : major / ratio, x_major ? major / ratio : major,
                   rng.uniform(-kPi, kPi)};
  };
  p.a = needle(rng.logUniform(0.2, 1.0));
  const double phi = rng.uniform(-kPi, kPi), range = rng.uniform(0.0, 100.0);
  p.a.center = {range * std::cos(phi), range * std::sin(phi)};
  p.b = needle(rng.logUniform(0.2, 1.0));
  const double heading = rng.uniform(-kPi, kPi), speed = rng.uniform(0.0, 1.0);
  const double wa = (rng.coin() ? 1.0 : -1.0) * rng.uniform(0.4, 3.0);
  // b turns in either sense at a rate at least 0.2 rad/s away from a's.
  double wb = wa;
  while (std::fabs(wb - wa) < 0.2) wb = (rng.coin() ? 1.0 : -1.0) * rng.uniform(0.4, 3.0);
  p.motion_a = {{speed * std::cos(heading), speed * std::sin(heading)}, wa};
  p.motion_b = {p.motion_a.velocity + Eigen::Vector2d(rng.uniform(-0.5, 0.5),
                                                      rng.uniform(-0.5, 0.5)),
                wb};
  p.horizon = 1.5;
  // Touching at t_pass from across the relative velocity, as placeAndScale(), with the flat side
  // of the chosen needle turned to face the other there.
  const double t_pass = rng.uniform(0.3, 0.7) * p.horizon;
  const Eigen::Vector2d n = acrossVelocity(rng, p.motion_b.velocity - p.motion_a.velocity);
  // The angle at t = 0 that puts an ellipse's short axis along n at t_pass.
  const auto facing = [&n, t_pass](const Ellipse& e, double omega) {
    const double short_axis = std::atan2(n.y(), n.x()) + (e.radius_x > e.radius_y ? kPi / 2 : 0.0);
    return short_axis - omega * t_pass;
  };
  const bool flats = contact == NeedleContact::kFlats;
  if (contact == NeedleContact::kFlatOfA || flats) p.a.angle = facing(p.a, wa);
  if (contact == NeedleContact::kFlatOfB || flats) p.b.angle = facing(p.b, wb);
  placeTouching(oracleMotionOf(p.a, p.motion_a), t_pass, n, out);
  p.text = motionPassText(p);
  return t_pass;
}

bool drawNeedlePairPass(RandomSource& rng, double ratio, NeedleContact contact, double target,
                        TurningPass* out) {
  TurningPass& p = *out;
  placeNeedlePair(rng, ratio, contact, out);
  p.pass = oracleGrazingPass(p.a, oracleMotionOf(p.a, p.motion_a), p.b,
                             oracleMotionOf(p.b, p.motion_b), p.horizon, target);
  if (!p.pass.found) return false;
  p.text = motionPassText(p);  // with the scaled radii
  return true;
}

}  // namespace ellipse_collision::core::test
