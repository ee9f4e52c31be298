#include "rotating_separation.h"

#include <cmath>
#include <limits>

#include "arc_motion.h"

namespace ellipse_collision::core::detail {
namespace {

// h and its derivatives along u. The rounding of the axis components ax, ay (~eps absolute)
// moves h by up to eps (r_x^2 |ax| + r_y^2 |ay|) / h, the distance of the support point from the
// centre along the axes (`reach`, >= h): for a needle seen near its flat side that is far more
// than eps h. It moves dh/dtheta by up to eps |r_x^2 - r_y^2| (|ax| + |ay|) / h (`dh_spread`).
struct SupportRates {
  double h, dh_dangle, curvature_radius;
  double reach, dh_spread;
  AxisShares shares;
};

SupportRates supportRates(const Ellipse& e, const SinCos& trig, const Eigen::Vector2d& u) {
  const double ax = u.x() * trig.cos + u.y() * trig.sin;  // u . x axis
  const double ay = u.y() * trig.cos - u.x() * trig.sin;  // u . y axis
  const double rx2 = e.radius_x * e.radius_x, ry2 = e.radius_y * e.radius_y;
  const double h = std::sqrt(rx2 * ax * ax + ry2 * ay * ay);
  const double fx = std::fabs(ax), fy = std::fabs(ay);
  // One division for the four quotients: each step evaluates this up to 16 times.
  const double inverse = 1.0 / h;
  // d(ax)/dangle = ay, d(ay)/dangle = -ax; turning u by phi is turning the shape by -phi.
  return {h,
          (rx2 - ry2) * ax * ay * inverse,
          rx2 * ry2 * (inverse * inverse * inverse),
          (rx2 * fx + ry2 * fy) * inverse,
          std::fabs(rx2 - ry2) * (fx + fy) * inverse,
          rx2 >= ry2 ? AxisShares{fx, fy} : AxisShares{fy, fx}};
}

}  // namespace

SeparationAlong separationAlong(const SinCosPair& trig, const Ellipse& a, const Ellipse& b,
                                const Eigen::Vector2d& centre_velocity, double wa, double wb,
                                const Eigen::Vector2d& u) {
  const SupportRates sa = supportRates(a, trig.first, u);
  const SupportRates sb = supportRates(b, trig.second, u);
  const Eigen::Vector2d centres = b.center - a.center;
  const double along = u.dot(centres);
  const double across = u.x() * centres.y() - u.y() * centres.x();  // (u turned +90 deg) . p
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double value = along - sa.h - sb.h;
  // h'' = rho - h for a support function of the normal angle, so f'' = -f - rho_a - rho_b.
  const double centre_rate = u.dot(centre_velocity);
  // The poses' angles are rounded to eps of their size, which moves each support point by its
  // reach times that: a pose whose angle is far from 0 turns by whole ulps (one of 6.9e274 rad
  // did not turn at all, while the rates below had it turn; a step passed a contact).
  return {value,
          centre_rate - wa * sa.dh_dangle - wb * sb.dh_dangle,
          16.0 * kEps *
              (std::fabs(along) + sa.reach * (1.0 + std::fabs(a.angle)) +
               sb.reach * (1.0 + std::fabs(b.angle))),
          across + sa.dh_dangle + sb.dh_dangle,
          -value - sa.curvature_radius - sb.curvature_radius,
          centre_rate,
          across,
          sa.dh_dangle,
          sb.dh_dangle,
          sa.dh_spread,
          sb.dh_spread,
          sa.shares,
          sb.shares};
}

bool rimNormal(const Ellipse& a, const Eigen::Vector2d& x, Eigen::Vector2d* normal) {
  const SinCos trig = sinCos(a.angle);
  const Eigen::Vector2d d = x - a.center;
  // In a's axes the rim is (x / r_x)^2 + (y / r_y)^2 = 1, whose gradient is the normal.
  const double nx = (trig.cos * d.x() + trig.sin * d.y()) / (a.radius_x * a.radius_x);
  const double ny = (trig.cos * d.y() - trig.sin * d.x()) / (a.radius_y * a.radius_y);
  const Eigen::Vector2d n(trig.cos * nx - trig.sin * ny, trig.sin * nx + trig.cos * ny);
  const double length = n.norm();
  if (!(length > 0.0)) return false;
  *normal = n / length;
  return true;
}

[[gnu::noinline]] SeparationAlong preciseSeparation(const RotatingPair& p, double t,
                                                    const Eigen::Vector2d& centre_velocity,
                                                    const Eigen::Vector2d& direction,
                                                    bool frame_of_a) {
  using Long = long double;
  const Long time = t;
  const auto exact = [](double high, double low) { return Long(high) + low; };
  Long px = exact(p.b.center.x(), p.low.b_center.x()) + exact(p.w.x(), p.low.w.x()) * time;
  Long py = exact(p.b.center.y(), p.low.b_center.y()) + exact(p.w.y(), p.low.w.y()) * time;
  if (p.hasArc()) {
    const Displacement<Long> arc =
        arcDisplacement<Long>(exact(p.a_arc_velocity.x(), p.low.a_arc_velocity.x()),
                              exact(p.a_arc_velocity.y(), p.low.a_arc_velocity.y()), p.wa, time);
    px -= arc.x;
    py -= arc.y;
  }
  // The frame's angle, and the other ellipse's angle in it.
  const Long angle_a = exact(p.a.angle, p.low.a_angle), angle_b = p.b.angle;
  const Long frame = frame_of_a ? angle_a + Long(p.wa) * time : angle_b + Long(p.wb) * time;
  const Long other = frame_of_a ? (angle_b - angle_a) + (Long(p.wb) - p.wa) * time
                                : (angle_a - angle_b) + (Long(p.wa) - p.wb) * time;
  const Long fc = std::cos(frame), fs = std::sin(frame);
  const auto toFrame = [&](Long x, Long y, Long* fx, Long* fy) {
    *fx = fc * x + fs * y;
    *fy = fc * y - fs * x;
  };
  const Long p_norm = std::hypot(px, py);
  toFrame(Long(px), Long(py), &px, &py);
  Long vx, vy;
  toFrame(centre_velocity.x(), centre_velocity.y(), &vx, &vy);
  struct Axes {
    Long c, s, rx2, ry2;
  };
  const auto axes = [](const Ellipse& e, Long c, Long s) {
    return Axes{c, s, Long(e.radius_x) * e.radius_x, Long(e.radius_y) * e.radius_y};
  };
  const Axes own = axes(frame_of_a ? p.a : p.b, 1, 0);
  const Axes turned = axes(frame_of_a ? p.b : p.a, std::cos(other), std::sin(other));
  const Axes& ea = frame_of_a ? own : turned;
  const Axes& eb = frame_of_a ? turned : own;
  struct Support {
    Long h, dh, rho, reach, spread;
    AxisShares shares;
  };
  // As supportRates(), in long double.
  const auto support = [](const Axes& e, Long ux, Long uy) {
    const Long ax = ux * e.c + uy * e.s, ay = uy * e.c - ux * e.s;
    const Long h = std::sqrt(e.rx2 * ax * ax + e.ry2 * ay * ay);
    const Long fx = std::fabs(ax), fy = std::fabs(ay);
    const double along_x = static_cast<double>(fx), along_y = static_cast<double>(fy);
    return Support{h,
                   (e.rx2 - e.ry2) * ax * ay / h,
                   e.rx2 * e.ry2 / (h * h * h),
                   (e.rx2 * fx + e.ry2 * fy) / h,
                   std::fabs(e.rx2 - e.ry2) * (fx + fy) / h,
                   e.rx2 >= e.ry2 ? AxisShares{along_x, along_y} : AxisShares{along_y, along_x}};
  };
  // The rounding of the frame's angle moves the other centre by |p| times it, and that of the
  // other's angle its support point by its reach times it.
  const Long frame_error = 1 + std::fabs(frame), other_error = 1 + std::fabs(other);
  const Long norm = std::hypot(Long(direction.x()), Long(direction.y()));
  Long ux, uy;
  toFrame(direction.x() / norm, direction.y() / norm, &ux, &uy);
  constexpr Long kEps = std::numeric_limits<Long>::epsilon();
  SeparationAlong best{};
  Long best_lower = -std::numeric_limits<Long>::infinity();
  for (int i = 0; i <= kDirectionSteps; ++i) {
    const Support sa = support(ea, ux, uy), sb = support(eb, ux, uy);
    const Long along = ux * px + uy * py, across = ux * py - uy * px;
    const Long value = along - sa.h - sb.h;
    const Support& so = frame_of_a ? sb : sa;
    const Long lower = value - 16 * kEps * (std::fabs(along) + p_norm * frame_error + sa.reach +
                                            sb.reach + so.reach * other_error);
    if (lower > best_lower) {
      best_lower = lower;
      const double centre_rate = static_cast<double>(ux * vx + uy * vy);
      // Shrunk by 2^-52 against the rounding to double.
      best = {static_cast<double>(lower) * (1.0 - 0x1p-52),
              static_cast<double>(centre_rate - p.wa * sa.dh - p.wb * sb.dh),
              0.0,
              static_cast<double>(across + sa.dh + sb.dh),
              static_cast<double>(-value - sa.rho - sb.rho),
              centre_rate,
              static_cast<double>(across),
              static_cast<double>(sa.dh),
              static_cast<double>(sb.dh),
              static_cast<double>(sa.spread),
              static_cast<double>(sb.spread),
              sa.shares,
              sb.shares};
    }
    // A Newton step on the angle of u where f is concave in it, as in bestSeparation().
    const Long curvature = -value - sa.rho - sb.rho;
    if (i == kDirectionSteps || !(curvature < 0)) break;
    const Long turn = -(across + sa.dh + sb.dh) / curvature;
    if (!(std::fabs(turn) < Long(0.5))) break;
    const Long c = std::cos(turn), s = std::sin(turn);
    const Long turned_x = c * ux - s * uy;
    uy = s * ux + c * uy;
    ux = turned_x;
  }
  return best;
}

}  // namespace ellipse_collision::core::detail
