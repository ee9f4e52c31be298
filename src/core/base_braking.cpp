#include "ellipse_collision/core/base_braking.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/path_motion.h"

namespace ellipse_collision::core {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Conservative advancement's cap on the steps; a grazing pass this long is claimed in contact.
constexpr int kMaxBrakingSteps = 2000;
// A gap below this share of the pair's size is a contact (the advancement would crawl).
constexpr double kContactGap = 1e-9;

}  // namespace

double brakingRate(const Twist& twist, const BaseDynamics& dynamics) {
  double rate = kInfinity;
  const double speed = std::hypot(twist.vx, twist.vy);
  if (speed > 0.0 && dynamics.linear_deceleration > 0.0) {
    rate = std::min(rate, dynamics.linear_deceleration / speed);
  }
  const double turn = std::fabs(twist.wz);
  if (turn > 0.0 && dynamics.angular_deceleration > 0.0) {
    rate = std::min(rate, dynamics.angular_deceleration / turn);
  }
  return rate;
}

ScaleProfile::ScaleProfile(double from, double to, double reaction, double hold, double rate) {
  const auto duration = [rate](double drop) { return drop > 0.0 ? drop / rate : 0.0; };
  double t = 0.0, sigma = 0.0;
  const auto add = [&](int i, double length, double scale, double slope) {
    if (!(length > 0.0)) slope = 0.0;  // an instant change (infinite rate) covers nothing
    pieces_[i] = {t, t + length, scale, slope, sigma};
    sigma += length * (scale + 0.5 * slope * length);
    t += length;
  };
  add(0, reaction, from, 0.0);
  // Toward `to`: down at the rate (for at most `hold`), up at once.
  const double ramp = to < from ? std::min(hold, duration(from - to)) : 0.0;
  add(1, ramp, from, ramp > 0.0 ? -rate : 0.0);
  const double held = ramp > 0.0 ? std::max(from - rate * ramp, to) : to;
  add(2, hold - ramp, held, 0.0);
  add(3, duration(held), held, held > 0.0 ? -rate : 0.0);
}

double ScaleProfile::scaleAt(double t) const {
  for (const Piece& p : pieces_) {
    if (t < p.end) return std::max(0.0, p.scale + p.slope * (std::max(t, p.start) - p.start));
  }
  return 0.0;
}

double ScaleProfile::sigmaAt(double t) const {
  for (const Piece& p : pieces_) {
    if (t < p.end) {
      const double dt = std::max(0.0, t - p.start);
      return p.sigma_before + dt * (p.scale + 0.5 * p.slope * dt);
    }
  }
  const Piece& last = pieces_[kPieces - 1];
  const double dt = last.end - last.start;
  return last.sigma_before + dt * (last.scale + 0.5 * last.slope * dt);
}

double ScaleProfile::timeAtSigma(double sigma) const {
  if (sigma <= 0.0) return 0.0;
  for (const Piece& p : pieces_) {
    const double length = p.end - p.start;
    const double covered = length * (p.scale + 0.5 * p.slope * length);
    if (p.sigma_before + covered < sigma) continue;
    const double need = sigma - p.sigma_before;
    if (p.slope == 0.0) return p.scale > 0.0 ? p.start + need / p.scale : kInfinity;
    // need = s dt + slope dt^2 / 2, the smaller root (slope < 0), in the stable form.
    const double disc = std::max(0.0, p.scale * p.scale + 2.0 * p.slope * need);
    return p.start + 2.0 * need / (p.scale + std::sqrt(disc));
  }
  return kInfinity;
}

double ScaleProfile::maxScale() const {
  double top = 0.0;
  for (const Piece& p : pieces_) top = std::max(top, p.scale);
  return top;
}

FirstContact brakingContact(const Ellipse& link, const Twist& twist, const ScaleProfile& profile,
                            const Ellipse& obstacle, const Motion& motion, double clearance) {
  // |D'| <= s(t) (|v_c| + |wz| (R_l - r_l)) + |v_o| + |w_o| (R_o - r_o): the link's centre moves
  // at s |v_c| (constant along its arc), each rim's support turns at most |w| (R - r) (Mirtich
  // 1996), so a step of D / V never passes the first time D reaches `clearance`.
  const Eigen::Vector2d centre_velocity(twist.vx - twist.wz * link.center.y(),
                                        twist.vy + twist.wz * link.center.x());
  const double link_rate =
      centre_velocity.norm() + std::fabs(twist.wz) * (link.radius_x > link.radius_y
                                                          ? link.radius_x - link.radius_y
                                                          : link.radius_y - link.radius_x);
  const double obstacle_rate =
      motion.velocity.norm() +
      std::fabs(motion.angular_velocity) * std::fabs(obstacle.radius_x - obstacle.radius_y);
  const double closing = profile.maxScale() * link_rate + obstacle_rate;
  const double size = boundingRadius(link) + boundingRadius(obstacle);
  const double end = profile.stopTime();
  double t = 0.0;
  for (int step = 0; step < kMaxBrakingSteps; ++step) {
    const Ellipse placed = linkAfter(link, twist, profile.sigmaAt(t));
    const Ellipse moved = movedBy(obstacle, motion, t);
    const Clearance now = distance(placed, moved);
    const double gap = now.separated ? now.distance - clearance : -1.0;
    if (gap <= kContactGap * size) return {true, t};
    if (!(closing > 0.0)) return {};
    // Make sure the step is never longer than the time to close the gap.
    t += gap / (closing * (1.0 + 1e-12));
    if (!(t <= end)) return {};
  }
  return {true, t};
}

}  // namespace ellipse_collision::core
