#include "ellipse_collision/core/free_space.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ellipse_collision::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// The angular half-width [rad] under which a disc of `radius` about `centre` is seen from the
/// origin, or pi when the disc holds the origin.
double halfWidthSeen(const Eigen::Vector2d& centre, double radius) {
  const double distance = centre.norm();
  if (!(distance > radius)) return kPi;
  // A few ulps wider: a beam grazing the disc is still looked at.
  return std::min(kPi, std::asin(radius / distance) * (1.0 + 1e-12) + 1e-12);
}

}  // namespace

FreeSpace::FreeSpace(std::vector<FreeSegment> segments) {
  segments.erase(std::remove_if(segments.begin(), segments.end(),
                                [](const FreeSegment& s) {
                                  return !(s.to > s.from) || !s.direction.allFinite();
                                }),
                 segments.end());
  std::vector<double> angles(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    angles[i] = std::atan2(segments[i].direction.y(), segments[i].direction.x());
  }
  std::vector<std::size_t> order(segments.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return angles[a] < angles[b]; });
  segments_.reserve(order.size());
  angles_.reserve(order.size());
  for (const std::size_t i : order) {
    segments_.push_back(segments[i]);
    angles_.push_back(angles[i]);
  }
}

template <typename Visit>
bool FreeSpace::anyWithin(double angle, double half_width, Visit visit) const {
  const auto range = [&](double lo, double hi) {
    const auto first = std::lower_bound(angles_.begin(), angles_.end(), lo);
    const auto last = std::upper_bound(angles_.begin(), angles_.end(), hi);
    for (auto it = first; it < last; ++it) {
      if (visit(segments_[static_cast<std::size_t>(it - angles_.begin())])) return true;
    }
    return false;
  };
  if (!(half_width < kPi)) return range(-kPi, kPi);
  const double lo = angle - half_width, hi = angle + half_width;
  // The window may wrap over +-pi: look at both ends.
  if (lo < -kPi) return range(lo + 2.0 * kPi, kPi) || range(-kPi, hi);
  if (hi > kPi) return range(lo, kPi) || range(-kPi, hi - 2.0 * kPi);
  return range(lo, hi);
}

bool FreeSpace::entered(const Ellipse& e, Eigen::Vector2d* where) const {
  // Normalised form q(x) = (x - c)^T M (x - c), M = R diag(1/rx^2, 1/ry^2) R^T.
  const double c = std::cos(e.angle), s = std::sin(e.angle);
  const double ix = 1.0 / (e.radius_x * e.radius_x), iy = 1.0 / (e.radius_y * e.radius_y);
  const double mxx = c * c * ix + s * s * iy, myy = s * s * ix + c * c * iy;
  const double mxy = c * s * (ix - iy);
  const Eigen::Vector2d mc(mxx * e.center.x() + mxy * e.center.y(),
                           mxy * e.center.x() + myy * e.center.y());
  const double cmc = e.center.dot(mc);
  if (cmc < 1.0 + kFreeSpaceMargin) {  // the origin inside (or on the rim)
    if (where) *where = Eigen::Vector2d::Zero();
    return true;
  }
  const double angle = std::atan2(e.center.y(), e.center.x());
  return anyWithin(angle, halfWidthSeen(e.center, boundingRadius(e)), [&](const FreeSegment& f) {
    const Eigen::Vector2d& d = f.direction;
    // q(t d) = A t^2 + B t + C over from < t < to, A > 0.
    const double a = mxx * d.x() * d.x() + 2.0 * mxy * d.x() * d.y() + myy * d.y() * d.y();
    const double b = -2.0 * d.dot(mc);
    const double t = std::clamp(-b / (2.0 * a), f.from, f.to);
    if (!((a * t + b) * t + cmc < 1.0 + kFreeSpaceMargin)) return false;
    if (where) *where = d;
    return true;
  });
}

bool FreeSpace::crossed(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        Eigen::Vector2d* where) const {
  const Eigen::Vector2d edge = b - a;
  const double length = edge.norm();
  // Distance from the origin to the segment.
  const double along = length > 0.0 ? std::clamp(-a.dot(edge) / (length * length), 0.0, 1.0) : 0.0;
  const Eigen::Vector2d nearest = a + along * edge;
  if (!(nearest.norm() > 1e-12)) {
    if (where) *where = Eigen::Vector2d::Zero();
    return true;
  }
  const Eigen::Vector2d mid = 0.5 * (a + b);
  return anyWithin(std::atan2(mid.y(), mid.x()), halfWidthSeen(mid, 0.5 * length),
                   [&](const FreeSegment& f) {
                     const double denominator = cross(f.direction, edge);
                     if (denominator == 0.0) return false;  // parallel: the ray misses the line
                     const double t = cross(a, edge) / denominator;
                     const double u = cross(a, f.direction) / denominator;
                     if (!(u >= 0.0 && u <= 1.0 && t > f.from && t < f.to)) return false;
                     if (where) *where = f.direction;
                     return true;
                   });
}

std::pair<const FreeSegment*, const FreeSegment*> FreeSpace::beside(
    const Eigen::Vector2d& first, const Eigen::Vector2d& last) const {
  constexpr double kApart = 1e-9;  // [rad]
  std::pair<const FreeSegment*, const FreeSegment*> found{nullptr, nullptr};
  if (segments_.empty()) return found;
  const double from = std::atan2(first.y(), first.x()), to = std::atan2(last.y(), last.x());
  // Clockwise of `from`: the last angle below it, else (wrapping over -pi) the last of all.
  auto below = std::lower_bound(angles_.begin(), angles_.end(), from - kApart);
  const std::size_t before = below == angles_.begin()
                                 ? angles_.size() - 1
                                 : static_cast<std::size_t>(below - angles_.begin()) - 1;
  // Counter-clockwise of `to`: the first angle above it, else (wrapping over pi) the first.
  auto above = std::upper_bound(angles_.begin(), angles_.end(), to + kApart);
  const std::size_t after =
      above == angles_.end() ? 0 : static_cast<std::size_t>(above - angles_.begin());
  const auto within = [](double angle) {  // the counter-clockwise angle in [0, 2 pi)
    return angle < 0.0 ? angle + 2.0 * kPi : angle;
  };
  const double span = within(to - from);
  if (within(from - angles_[before]) > kApart && within(from - angles_[before]) < kPi &&
      within(angles_[before] - from) > span) {
    found.first = &segments_[before];
  }
  if (within(angles_[after] - to) > kApart && within(angles_[after] - to) < kPi &&
      within(angles_[after] - from) > span) {
    found.second = &segments_[after];
  }
  return found;
}

double FreeSpace::clearance(const Eigen::Vector2d& p, double radius) const {
  double nearest = std::min(radius, p.norm());
  anyWithin(std::atan2(p.y(), p.x()), halfWidthSeen(p, radius), [&](const FreeSegment& f) {
    const double t = std::clamp(p.dot(f.direction), f.from, f.to);
    nearest = std::min(nearest, (p - t * f.direction).norm());
    return false;
  });
  return nearest;
}

}  // namespace ellipse_collision::core
