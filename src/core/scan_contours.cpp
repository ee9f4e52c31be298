#include "ellipse_collision/core/scan_contours.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "ellipse_collision/core/enclosing_ellipse.h"
#include "ellipse_collision/core/point_clusters.h"

namespace ellipse_collision::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The bin of cloudView() holding the direction of `p`.
std::size_t cloudBin(const Eigen::Vector2d& p) {
  const double bin = std::floor((std::atan2(p.y(), p.x()) + kPi) / kCloudBinAngle);
  return std::min(kCloudBins - 1, static_cast<std::size_t>(std::max(bin, 0.0)));
}

/// The angle between the directions of a and b as seen from the origin, in [0, pi] [rad].
double angleBetween(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
}

/// The return of `run` farthest from the chord between its ends (Douglas-Peucker's split point),
/// the middle one when none is off the chord; an index strictly inside the run.
std::size_t splitIndex(const std::vector<SensorReturn>& run, std::size_t begin, std::size_t end) {
  const Eigen::Vector2d a = run[begin].point, chord = run[end - 1].point - a;
  const double length = chord.norm();
  std::size_t best = begin + (end - begin) / 2;
  double farthest = 0.0;
  for (std::size_t i = begin + 1; i + 1 < end; ++i) {
    const Eigen::Vector2d v = run[i].point - a;
    const double off =
        length > 0.0 ? std::abs(chord.x() * v.y() - chord.y() * v.x()) / length : v.norm();
    if (off > farthest) {
      farthest = off;
      best = i;
    }
  }
  return best;
}

/// The signed angle from a's direction to b's, in (-pi, pi] [rad].
double signedAngle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

/// Which side of the run [begin, end) (returns in angular order) the beam along `ray` passes:
/// -1 before its return begin + inner, +1 after its return end - 1 - inner, 0 between them (or
/// the origin, ray zero). Needs end - begin > 2 inner.
int sideOf(const std::vector<SensorReturn>& run, std::size_t begin, std::size_t end,
           const Eigen::Vector2d& ray, std::size_t inner = 0) {
  if (ray.isZero()) return 0;
  const Eigen::Vector2d a = run[begin + inner].point, b = run[end - 1 - inner].point;
  const double span = signedAngle(a, b), toward = signedAngle(a, ray);
  const double s = span < 0.0 ? -1.0 : 1.0;  // orient the run from 0 to |span|
  if (s * toward < 0.0) return -1;
  if (s * toward > s * span) return 1;
  return 0;
}

/// The index strictly inside the run [begin, end) (returns in angular order) before which the
/// beam along `ray` passes between two consecutive returns, clear of both returns' own beams; 0
/// when it passes between none (beyond an end, along a return's beam, or the origin).
std::size_t cutAtBeam(const std::vector<SensorReturn>& run, std::size_t begin, std::size_t end,
                      const Eigen::Vector2d& ray) {
  constexpr double kApart = 1e-9;  // [rad]: closer, the beam is taken for the return's own
  if (ray.isZero() || end - begin < 2) return 0;
  const Eigen::Vector2d a = run[begin].point;
  const double s = signedAngle(a, run[end - 1].point) < 0.0 ? -1.0 : 1.0;
  const double toward = s * signedAngle(a, ray);
  double previous = 0.0;
  for (std::size_t i = begin + 1; i < end; ++i) {
    const double here = s * signedAngle(a, run[i].point);
    if (toward < here) return toward > previous + kApart && toward < here - kApart ? i : 0;
    previous = here;
  }
  return 0;
}

/// The principal direction of `points` (of their covariance's larger eigenvalue) and their
/// half-width across it [m].
std::pair<Eigen::Vector2d, double> principalBand(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  double xx = 0.0, xy = 0.0, yy = 0.0;
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d q = p - mean;
    xx += q.x() * q.x(), xy += q.x() * q.y(), yy += q.y() * q.y();
  }
  const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);
  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
  double lo = 0.0, hi = 0.0;
  for (const Eigen::Vector2d& p : points) {
    const double across = direction.x() * (p.y() - mean.y()) - direction.y() * (p.x() - mean.x());
    lo = std::min(lo, across), hi = std::max(hi, across);
  }
  return {direction, 0.5 * (hi - lo)};
}

/// The circle through `points` by least squares (I. Kasa, "A circle fitting procedure and its
/// error analysis", IEEE Trans. Instrum. Meas. 25, 1976: x^2 + y^2 + D x + E y + F = 0), grown to
/// contain every point; nothing when the points are (nearly) collinear or not round (some point
/// more than a fifth of the radius inside the circle).
std::optional<Ellipse> enclosingCircleFit(const std::vector<Eigen::Vector2d>& points) {
  // Centred on the mean for conditioning.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d q = p - mean;
    const Eigen::Vector3d row(q.x(), q.y(), 1.0);
    normal += row * row.transpose();
    rhs -= row * q.squaredNorm();
  }
  const Eigen::Vector3d def = normal.ldlt().solve(rhs);
  if (!def.allFinite()) return std::nullopt;
  const Eigen::Vector2d centre = mean - 0.5 * def.head<2>();
  double radius = 0.0, nearest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& p : points) {
    const double distance = (p - centre).norm();
    radius = std::max(radius, distance), nearest = std::min(nearest, distance);
  }
  // Round: every point within a fifth of the radius of the circle (a pillar's arc with noise;
  // not a corner, whose middle lies far inside the circle through its ends).
  if (!(radius - nearest <= 0.2 * radius)) return std::nullopt;
  // A few ulps more, so that rounding leaves every point inside.
  radius *= 1.0 + 1e-12;
  if (!(radiusOk(radius) && coordinateOk(centre.x()) && coordinateOk(centre.y()))) {
    return std::nullopt;
  }
  return Ellipse{centre, radius, radius, 0.0};
}

/// Ellipses around `points` that fit inside the wedge between the beams `lo` and `hi` (unit
/// directions, lo clockwise of hi, less than half a turn apart), the radius along the wedge at
/// least `min_radius` (across it as the wedge allows), smallest area first. Each has its axes along
/// and across the wedge's bisector m and its centre at x m: it stays inside the wedge |y| <= k x (k
/// the tangent of half the wedge's angle) exactly when its support across each side is no more than
/// the side's, b^2 + k^2 a^2 <= k^2 x^2; a is then the shortest that contains the points with b as
/// large as that allows. A run between two beams passing it by (half a pole beside its middle beam
/// without return, its other edge grazed) fits there when every ellipse bulging past its ends does
/// not. O(n) per centre tried.
std::vector<Ellipse> wedgeEllipses(const std::vector<Eigen::Vector2d>& points,
                                   const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                                   double min_radius) {
  std::vector<Ellipse> found;
  const Eigen::Vector2d sum = lo + hi;
  if (!(sum.norm() > 1e-12) || !(signedAngle(lo, hi) > 0.0)) return found;
  const Eigen::Vector2d m = sum.normalized();
  const double k = signedAngle(m, hi) > 0.0 ? std::tan(signedAngle(m, hi)) : 0.0;
  if (!(k > 0.0)) return found;
  std::vector<Eigen::Vector2d> local;  // (along m, across m)
  local.reserve(points.size());
  double near = std::numeric_limits<double>::infinity(), far = 0.0;
  for (const Eigen::Vector2d& p : points) {
    local.emplace_back(m.dot(p), m.x() * p.y() - m.y() * p.x());
    if (!(std::abs(local.back().y()) < k * local.back().x())) return found;  // outside the wedge
    near = std::min(near, local.back().x()), far = std::max(far, local.back().x());
  }
  // b a hair inside the wedge (the exact free-space test judges the rest).
  const double narrowed = k * (1.0 - 1e-9), kk = narrowed * narrowed;
  // The worst normalised radius of a point for a^2 = u, b^2 = kk (x^2 - u) (convex in u).
  const auto worst = [&](double x, double u) {
    double w = 0.0;
    for (const Eigen::Vector2d& q : local) {
      w = std::max(w, (q.x() - x) * (q.x() - x) / u + q.y() * q.y() / (kk * (x * x - u)));
    }
    return w;
  };
  constexpr int kCentres = 16;
  const double reach = 2.0 * (far - near) + 2.0 * min_radius;
  std::vector<std::pair<double, Ellipse>> by_area;
  for (int j = 0; j <= kCentres; ++j) {
    const double x = near + reach * j / kCentres;
    // a >= min_radius and b >= kMinRadius bound u = a^2.
    const double smallest = min_radius * min_radius;
    double u_lo = smallest;
    double u_hi = x * x - (2.0 * kMinRadius / k) * (2.0 * kMinRadius / k);
    if (!(u_hi > u_lo)) continue;
    for (int step = 0; step < 60; ++step) {  // golden section on the convex worst()
      const double a1 = u_lo + 0.381966 * (u_hi - u_lo), a2 = u_lo + 0.618034 * (u_hi - u_lo);
      if (worst(x, a1) < worst(x, a2)) {
        u_hi = a2;
      } else {
        u_lo = a1;
      }
    }
    if (!(worst(x, 0.5 * (u_lo + u_hi)) <= 1.0 - 1e-9)) continue;
    // The shortest a that still contains the points (worst() falls up to its minimum): the
    // ellipse reaches least far toward the sensor, into the free parts of the run's own beams.
    double shorter = smallest, longer = 0.5 * (u_lo + u_hi);
    for (int step = 0; step < 60; ++step) {
      const double mid = 0.5 * (shorter + longer);
      (worst(x, mid) <= 1.0 - 1e-9 ? longer : shorter) = mid;
    }
    const double u = longer;
    const double a = std::sqrt(u), b = narrowed * std::sqrt(x * x - u);
    if (!(radiusOk(a) && radiusOk(b))) continue;
    // Contains every point as the ellipse will be stored (a and b rounded), not only as u.
    const auto inside = [&](const Eigen::Vector2d& q) {
      const double dx = (q.x() - x) / a, dy = q.y() / b;
      return dx * dx + dy * dy <= 1.0 - 1e-9;
    };
    if (!std::all_of(local.begin(), local.end(), inside)) continue;
    const Eigen::Vector2d centre = x * m;
    if (!(coordinateOk(centre.x()) && coordinateOk(centre.y()))) continue;
    by_area.emplace_back(a * b, Ellipse{centre, a, b, std::atan2(m.y(), m.x())});
  }
  std::sort(by_area.begin(), by_area.end(),
            [](const auto& l, const auto& r) { return l.first < r.first; });
  for (const auto& [area, e] : by_area) found.push_back(e);
  return found;
}

}  // namespace

BeamReading readBeam(double r, double range_min, double range_max) {
  // Written so that NaN ranges and NaN limits give Unknown.
  if (!(r >= std::max(range_min, 0.0) && range_max >= range_min)) return BeamReading::Unknown;
  if (r > range_max) return BeamReading::NoReturn;  // +inf too
  return r <= kMaxCoordinate ? BeamReading::Return : BeamReading::Unknown;
}

SensorView scanView(const std::vector<float>& ranges, double angle_min, double angle_increment,
                    double range_min, double range_max, double free_space_tolerance) {
  ScanBeams beams;
  SensorView view;
  scanView(ranges, angle_min, angle_increment, range_min, range_max, free_space_tolerance, beams,
           view);
  return view;
}

void ScanBeams::update(std::size_t count, double angle_min, double angle_increment) {
  // Bit for bit: -0.0 and 0.0 give directions of different signs.
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  if (set_ && count == finite_.size() && same(angle_min, angle_min_) &&
      same(angle_increment, angle_increment_)) {
    return;
  }
  set_ = true;
  angle_min_ = angle_min;
  angle_increment_ = angle_increment;
  finite_.assign(count, 0);
  directions_.assign(count, Eigen::Vector2d::Zero());
  angles_.assign(count, 0.0);
  order_.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const double angle = angle_min + static_cast<double>(i) * angle_increment;
    if (!std::isfinite(angle)) continue;
    finite_[i] = 1;
    directions_[i] = Eigen::Vector2d(std::cos(angle), std::sin(angle));
    angles_[i] = std::atan2(directions_[i].y(), directions_[i].x());
    order_.push_back(i);
  }
  std::stable_sort(order_.begin(), order_.end(),
                   [&](std::size_t a, std::size_t b) { return angles_[a] < angles_[b]; });
}

void scanView(const std::vector<float>& ranges, double angle_min, double angle_increment,
              double range_min, double range_max, double free_space_tolerance, ScanBeams& beams,
              SensorView& view) {
  beams.update(ranges.size(), angle_min, angle_increment);
  view.returns.clear();
  view.returns.reserve(ranges.size());
  const double lowest = std::max(range_min, 0.0);
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    if (beams.finite(i) && readBeam(ranges[i], range_min, range_max) == BeamReading::Return) {
      view.returns.push_back({static_cast<double>(ranges[i]) * beams.direction(i), i});
    }
  }
  // The free segments in the free space's order (by angle, ties in beam order): as FreeSpace()
  // would sort the beams', without the atan2 calls and the sort.
  view.free_space.clear();
  for (const std::size_t i : beams.order()) {
    const double r = ranges[i];
    switch (readBeam(r, range_min, range_max)) {
      case BeamReading::Return:
        view.free_space.appendInOrder({beams.direction(i), lowest, r - free_space_tolerance},
                                      beams.freeSpaceAngle(i));
        break;
      case BeamReading::NoReturn:
        view.free_space.appendInOrder(
            {beams.direction(i), lowest, std::min(range_max, kMaxCoordinate), true},
            beams.freeSpaceAngle(i));
        break;
      case BeamReading::Unknown:
        break;
    }
  }
  const double turn = std::abs(angle_increment) * static_cast<double>(ranges.size());
  view.full_turn = std::abs(turn - 2.0 * kPi) <= 0.5 * std::abs(angle_increment);
}

SensorView cloudView(const std::vector<Eigen::Vector2d>& points, double free_space_tolerance) {
  SensorView view;
  view.returns.reserve(points.size());
  std::vector<double> angles;
  angles.reserve(points.size());
  for (const Eigen::Vector2d& p : points) {
    if (!(coordinateOk(p.x()) && coordinateOk(p.y()))) continue;
    view.returns.push_back({p, 0});
    angles.push_back(std::atan2(p.y(), p.x()));
  }
  // Sort by angle (then range, so that each bin's nearest point comes first).
  std::vector<std::size_t> order(view.returns.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (angles[a] != angles[b]) return angles[a] < angles[b];
    return view.returns[a].point.squaredNorm() < view.returns[b].point.squaredNorm();
  });
  std::vector<SensorReturn> sorted;
  sorted.reserve(order.size());
  std::vector<std::size_t> nearest(kCloudBins, order.size());
  for (const std::size_t i : order) {
    const Eigen::Vector2d p = view.returns[i].point;
    // The same point again (a vertical surface seen by several rings) adds nothing.
    if (!sorted.empty() && sorted.back().point == p) continue;
    const std::size_t key = cloudBin(p);
    if (nearest[key] == order.size() ||
        p.squaredNorm() < sorted[nearest[key]].point.squaredNorm()) {
      nearest[key] = sorted.size();
    }
    sorted.push_back({p, key});
  }
  std::vector<FreeSegment> free;
  for (const std::size_t i : nearest) {
    if (i == order.size()) continue;
    const double r = sorted[i].point.norm();
    if (!(r > 0.0)) continue;
    free.push_back({sorted[i].point / r, 0.0, r - free_space_tolerance});
  }
  view.returns = std::move(sorted);
  view.free_space = FreeSpace(std::move(free));
  view.full_turn = true;
  return view;
}

bool sameContour(const Eigen::Vector2d& p, const Eigen::Vector2d& q, double range_noise_sigma,
                 double join_distance) {
  const double gap = (p - q).norm();
  if (gap < join_distance) return true;
  const double dphi = angleBetween(p, q);
  if (!(dphi < kBreakpointAngle)) return false;
  return gap <=
         p.norm() * std::sin(dphi) / std::sin(kBreakpointAngle - dphi) + 3.0 * range_noise_sigma;
}

std::vector<std::vector<SensorReturn>> breakContours(const SensorView& view,
                                                     double range_noise_sigma, double join_distance,
                                                     std::size_t min_points) {
  std::vector<std::vector<SensorReturn>> contours;
  const auto& returns = view.returns;
  for (std::size_t i = 0; i < returns.size(); ++i) {
    if (i == 0 ||
        !sameContour(returns[i - 1].point, returns[i].point, range_noise_sigma, join_distance)) {
      contours.emplace_back();
    }
    contours.back().push_back(returns[i]);
  }
  // Across the scan's start: the last contour continues into the first.
  if (view.full_turn && contours.size() > 1 &&
      sameContour(returns.back().point, returns.front().point, range_noise_sigma, join_distance)) {
    contours.back().insert(contours.back().end(), contours.front().begin(), contours.front().end());
    contours.erase(contours.begin());
  }
  const std::size_t minimum = std::max<std::size_t>(min_points, 1);
  contours.erase(std::remove_if(contours.begin(), contours.end(),
                                [&](const auto& c) { return c.size() < minimum; }),
                 contours.end());
  return contours;
}

std::vector<std::vector<SensorReturn>> cloudContours(const SensorView& view, double join_distance,
                                                     std::size_t min_points) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(view.returns.size());
  for (const SensorReturn& r : view.returns) points.push_back(r.point);
  std::vector<std::vector<SensorReturn>> contours;
  for (const auto& cluster : clusterUnorderedPoints(points, join_distance, min_points)) {
    contours.emplace_back();
    contours.back().reserve(cluster.size());
    for (const Eigen::Vector2d& p : cluster) contours.back().push_back({p, cloudBin(p)});
  }
  return contours;
}

namespace {

/// What the candidates of contourEllipses() make of one run of returns.
struct RunFit {
  enum class Outcome {
    Accepted,     ///< `ellipse` stays out of the free space
    KeptAnyway,   ///< a single return whose every circle enters it: `ellipse` kept, `note` says so
    Failed,       ///< no ellipse could be made (`note`): the run is dropped, and said
    SplitAtOnce,  ///< split, with no other candidate tried: its chord crosses free space, or a
                  ///< round arc's circle enters a beam passing between its returns (`rays`)
    Split,        ///< every candidate entered the free space (`rays`: the beams entered)
  };
  Outcome outcome{Outcome::Split};
  ContourEllipse ellipse;
  std::string note;
  std::vector<Eigen::Vector2d> rays;
};

/// The candidates of contourEllipses(), in its order, for the run [begin, end) of `contour`.
/// With a `margin` [m], a candidate is accepted only when it stays out of the free space with
/// both radii grown by the margin. `points` is scratch space.
RunFit fitRun(const std::vector<SensorReturn>& contour, std::size_t begin, std::size_t end,
              const FreeSpace& free_space, double min_radius, std::vector<Eigen::Vector2d>& points,
              double margin = 0.0) {
  const std::size_t n = end - begin;
  RunFit fit;
  fit.ellipse = ContourEllipse{Ellipse{}, contour[begin].key, n, contour[end - 1].key, false};
  Eigen::Vector2d crossing;
  if (n >= 3 && free_space.crossed(contour[begin].point, contour[end - 1].point, &crossing)) {
    fit.rays.push_back(crossing);
    fit.outcome = RunFit::Outcome::SplitAtOnce;
    return fit;
  }
  points.clear();
  for (std::size_t i = begin; i < end; ++i) points.push_back(contour[i].point);
  // Takes `candidate` when it stays out of the free space.
  const auto accepted = [&](const Ellipse& candidate, bool reduced) {
    Eigen::Vector2d ray;
    Ellipse grown = candidate;
    grown.radius_x += margin;
    grown.radius_y += margin;
    if (free_space.entered(margin > 0.0 ? grown : candidate, &ray)) {
      fit.rays.push_back(ray);
      return false;
    }
    fit.ellipse.ellipse = candidate;
    fit.ellipse.radius_reduced = reduced;
    fit.outcome = RunFit::Outcome::Accepted;
    return true;
  };
  // A thin run (a wall's returns) is one whose band fits within min_radius.
  const auto [direction, half_width] = principalBand(points);
  const bool thin = n >= 3 && std::sqrt(2.0) * half_width <= min_radius;
  if (n >= 3) {
    // 1. A round object's arc: the circle it lies on (not the huge one of a nearly straight
    // run: at most the chord's length in radius). O(n).
    const std::optional<Ellipse> circle = enclosingCircleFit(points);
    const double chord = (points.back() - points.front()).norm();
    // A thin arc is tried too: a pole seen by many beams is a shallow arc, and its circle, not
    // the band ellipse bulging past the arc's ends into the beams grazing it, is what stays out.
    if (circle && circle->radius_x >= min_radius && circle->radius_x <= chord) {
      if (accepted(*circle, false)) return fit;
      // A round arc whose circle meets a beam (where the beams graze the object, its circle
      // grown by the range noise reaches their free parts; a beam without return between its
      // returns): every ellipse as round would, so the arc is split with no costlier
      // candidate tried, until its parts are thin enough for band ellipses. But a beam beyond
      // an end of the arc that cuts deep through its circle (the middle beam of a pole that
      // returned nothing, next to half the pole's arc) leaves room for a flatter ellipse
      // beside it, and a thin arc's band ellipse is flatter: the candidates below are tried.
      const Eigen::Vector2d ray = fit.rays.back();
      const double depth = std::abs(ray.x() * circle->center.y() - ray.y() * circle->center.x());
      if (thin) {
        fit.rays.pop_back();
      } else if (sideOf(contour, begin, end, ray) == 0 || !(depth < 0.5 * circle->radius_x)) {
        fit.outcome = RunFit::Outcome::SplitAtOnce;
        return fit;
      }
    }
  }
  // 2. The enclosing ellipse; for a thin run the band's ellipse, O(n), about what the
  // minimum-area optimiser would give at far more cost.
  const EnclosingEllipse enclosing = thin ? bandEllipse(points, direction, min_radius)
                                          : enclosingEllipseWithMinRadius(points, min_radius);
  if (!enclosing.ok()) {
    fit.outcome = RunFit::Outcome::Failed;
    fit.note = "returns " + std::to_string(contour[begin].key) + " to " +
               std::to_string(contour[end - 1].key) + ": " + enclosing.error;
    return fit;
  }
  if (accepted(enclosing.ellipse, false)) return fit;
  if (n >= 3 && !thin) {
    // 3. A convex object bulges the enclosing ellipse out in front of it: enclose the run
    // with its shadow (each return pushed back along its ray by the chord's length, space the
    // sensor cannot see), which rounds the ellipse onto the object.
    const double depth = (points.back() - points.front()).norm();
    for (std::size_t i = 0; i < n; ++i) {
      points.push_back(points[i] * (1.0 + depth / points[i].norm()));
    }
    const EnclosingEllipse shadowed = enclosingEllipseWithMinRadius(points, min_radius);
    points.resize(n);
    if (shadowed.ok() && accepted(shadowed.ellipse, false)) return fit;
  }
  // 4. A thin run (a wall seen at a glancing angle, one or two returns) whose min_radius
  // ellipse reaches into the free parts of its neighbouring beams: the smaller radius the
  // free space leaves, half the smallest clearance of its returns.
  if (inscribedRadius(enclosing.ellipse) <= min_radius * (1.0 + 1e-9)) {
    double clearance = min_radius;
    for (const Eigen::Vector2d& p : points) {
      clearance = std::min(clearance, free_space.clearance(p, min_radius));
    }
    const double reduced = std::max(0.5 * clearance, kMinRadius);
    const EnclosingEllipse thinner = thin ? bandEllipse(points, direction, reduced)
                                          : enclosingEllipseWithMinRadius(points, reduced);
    if (thinner.ok() && accepted(thinner.ellipse, true)) return fit;
    if (thinner.ok() && n == 1) {
      // Another beam through the return itself: kept all the same, and said.
      fit.ellipse.ellipse = thinner.ellipse;
      fit.ellipse.radius_reduced = true;
      fit.outcome = RunFit::Outcome::KeptAnyway;
      fit.note = "return " + std::to_string(contour[begin].key) +
                 ": no circle around it stays out of the free space";
      return fit;
    }
  }
  // 5. A run between two beams that pass it by (beyond its farthest return), one of them a
  // beam without return (a drop-out on a dark or shiny object, or nothing behind it): the
  // ellipse that fits in the wedge between them. Only there: where both beams end on
  // something behind (a pillar before a wall), range noise would make the wedge's fit come and
  // go from scan to scan, and the split the other candidates ask for stays put. The beams it
  // enters are not noted: the split that follows is the one the other candidates asked for.
  if (n >= 2) {
    const bool ccw = signedAngle(points.front(), points.back()) > 0.0;
    const auto [lo, hi] = ccw ? free_space.beside(points.front(), points.back())
                              : free_space.beside(points.back(), points.front());
    double farthest = 0.0;
    for (const Eigen::Vector2d& p : points) farthest = std::max(farthest, p.norm());
    if (lo && hi && lo->to > farthest && hi->to > farthest && (lo->no_return || hi->no_return)) {
      const std::size_t noted = fit.rays.size();
      for (const Ellipse& e : wedgeEllipses(points, lo->direction, hi->direction, min_radius)) {
        if (accepted(e, e.radius_y < min_radius)) return fit;
      }
      fit.rays.resize(noted);
    }
  }
  if (n == 1) {  // not even the reduced circle is a valid ellipse: kept, and said
    fit.ellipse.ellipse = enclosing.ellipse;
    fit.outcome = RunFit::Outcome::KeptAnyway;
    fit.note = "return " + std::to_string(contour[begin].key) +
               ": its circle of min_radius enters the free space";
    return fit;
  }
  fit.outcome = RunFit::Outcome::Split;
  return fit;
}

/// Where `contour` is cut before the split loop: before each return (not the first) whose key
/// is in `hints` (sorted) and differs from the key before it. Returns the cut indices, ascending.
std::vector<std::size_t> hintedCuts(const std::vector<SensorReturn>& contour,
                                    const std::vector<std::size_t>& hints) {
  std::vector<std::size_t> cuts;
  if (hints.empty()) return cuts;
  for (std::size_t i = 1; i < contour.size(); ++i) {
    if (contour[i].key != contour[i - 1].key &&
        std::binary_search(hints.begin(), hints.end(), contour[i].key)) {
      cuts.push_back(i);
    }
  }
  return cuts;
}

/// Where a run is split when an ellipse around it met the beams `rays`: where one of them
/// passes between two consecutive returns and its free part crosses the segment between them
/// (every ellipse around both would enter it: a cut the free space requires, such as a beam
/// without return through an object); else at splitIndex().
std::size_t cutOrSplitIndex(const std::vector<SensorReturn>& contour, std::size_t begin,
                            std::size_t end, const std::vector<Eigen::Vector2d>& rays,
                            const FreeSpace& free_space) {
  for (const Eigen::Vector2d& ray : rays) {
    const std::size_t at = cutAtBeam(contour, begin, end, ray);
    if (at != 0 && free_space.crossed(contour[at - 1].point, contour[at].point)) return at;
  }
  return splitIndex(contour, begin, end);
}

}  // namespace

ContourEllipses contourEllipses(const std::vector<std::vector<SensorReturn>>& contours,
                                const FreeSpace& free_space, double min_radius,
                                const std::vector<std::size_t>& split_hints, double hint_margin) {
  ContourEllipses result;
  if (radiusViolation(min_radius)) {
    // The same words as enclosingEllipseWithMinRadius(), which checks it the same way.
    result.error = enclosingEllipseWithMinRadius({Eigen::Vector2d::Zero()}, min_radius).error;
    return result;
  }
  std::vector<Eigen::Vector2d> points;
  for (const auto& contour : contours) {
    // Runs still to do, the next one on top: the output keeps contour order.
    struct Run {
      std::size_t begin, end;
      bool peel_front, peel_back;  // may an end return still be split off alone
    };
    std::vector<Run> todo;
    const std::vector<std::size_t> cuts = hintedCuts(contour, split_hints);
    for (std::size_t k = cuts.size() + 1; k-- > 0;) {
      todo.push_back(
          {k == 0 ? 0 : cuts[k - 1], k == cuts.size() ? contour.size() : cuts[k], true, true});
    }
    std::vector<std::pair<std::size_t, std::size_t>> kept;  // [begin, end) of each ellipse
    while (!todo.empty()) {
      const Run run = todo.back();
      const std::size_t begin = run.begin, end = run.end, n = end - begin;
      todo.pop_back();
      // Two runs [begin, at) and [at, end), whose new ends may be peeled, the old ones as before.
      const auto split = [&](std::size_t at) {
        todo.push_back({at, end, true, run.peel_back});
        todo.push_back({begin, at, run.peel_front, true});
      };
      RunFit fit = fitRun(contour, begin, end, free_space, min_radius, points);
      switch (fit.outcome) {
        case RunFit::Outcome::Accepted:
          result.ellipses.push_back(fit.ellipse);
          kept.emplace_back(begin, end);
          continue;
        case RunFit::Outcome::KeptAnyway:
          result.ellipses.push_back(fit.ellipse);
          kept.emplace_back(begin, end);
          result.skipped.push_back(std::move(fit.note));
          continue;
        case RunFit::Outcome::Failed:
          result.skipped.push_back(std::move(fit.note));
          continue;
        case RunFit::Outcome::SplitAtOnce:
          split(cutOrSplitIndex(contour, begin, end, fit.rays, free_space));
          continue;
        case RunFit::Outcome::Split:
          break;
      }
      if (n == 2) {
        split(begin + 1);
        continue;
      }
      // Where a candidate entered a beam beyond one end, that end's return goes alone (once per
      // end: a face seen at a glancing angle would otherwise be peeled return by return); else
      // the Douglas-Peucker split.
      int side = 0;
      for (const Eigen::Vector2d& ray : fit.rays) {
        const int s = sideOf(contour, begin, end, ray);
        if ((s < 0 && run.peel_front) || (s > 0 && run.peel_back)) {
          side = s;
          break;
        }
      }
      if (side < 0) {
        todo.push_back({begin + 1, end, false, run.peel_back});
        todo.push_back({begin, begin + 1, false, false});
      } else if (side > 0) {
        todo.push_back({end - 1, end, false, false});
        todo.push_back({begin, end - 1, run.peel_front, false});
      } else {
        split(splitIndex(contour, begin, end));
      }
    }
    // A hinted cut that two neighbouring runs would not need (their union is one ellipse that
    // stays out of the free space by hint_margin) is reported, so that the caller can let it go
    // (ScanCutMemory). The margin is the hysteresis: a cut noise needs now and then is kept.
    for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
      const std::size_t at = kept[k].second;
      if (kept[k + 1].first != at || !std::binary_search(cuts.begin(), cuts.end(), at)) continue;
      if (fitRun(contour, kept[k].first, kept[k + 1].second, free_space, min_radius, points,
                 hint_margin)
              .outcome == RunFit::Outcome::Accepted) {
        result.unneeded_hints.push_back(contour[at].key);
      }
    }
  }
  return result;
}

}  // namespace ellipse_collision::core
