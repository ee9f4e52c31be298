#include "twist_oracle.h"

#include <quadmath.h>

#include "ellipse_collision/core/overlap.h"

namespace ellipse_collision::core::twist_oracle {

// ---- the oracle: the arc about the instantaneous centre, in quad precision ------------------
// Independent of poseAfter()'s sinc form: the frame's origin turns about the centre
// r = (-vy, vx) / wz, so p(t) = r - R(wz t) r; quad keeps ~20 digits even where r is 1e12 m out.
Ellipse oracleLinkAt(const Ellipse& link, const Twist& twist, double t) {
  __float128 px = 0, py = 0;
  const __float128 th = static_cast<__float128>(twist.wz) * t;
  const __float128 c = cosq(th), s = sinq(th);
  if (twist.wz == 0.0) {
    px = static_cast<__float128>(twist.vx) * t;
    py = static_cast<__float128>(twist.vy) * t;
  } else {
    const __float128 rx = -static_cast<__float128>(twist.vy) / twist.wz;
    const __float128 ry = static_cast<__float128>(twist.vx) / twist.wz;
    px = rx - (c * rx - s * ry);
    py = ry - (s * rx + c * ry);
  }
  Ellipse e = link;
  e.center.x() = static_cast<double>(px + c * link.center.x() - s * link.center.y());
  e.center.y() = static_cast<double>(py + s * link.center.x() + c * link.center.y());
  e.angle = static_cast<double>(link.angle + th);
  return e;
}

Ellipse obstacleAt(const Ellipse& o, const Motion& m, double t) {
  Ellipse e = o;
  e.center += m.velocity * t;
  e.angle += m.angular_velocity * t;
  return e;
}

// First overlap() along the exact motion: `samples` uniform times, then 60 bisections of the
// first crossing. -1 when none is seen (a contact shorter than horizon / samples can be missed).
double scannedContact(const Ellipse& link, const Twist& twist, const Ellipse& obstacle,
                      const Motion& motion, double horizon, int samples) {
  return firstScanned(
      [&](double t) {
        return overlap(oracleLinkAt(link, twist, t), obstacleAt(obstacle, motion, t));
      },
      horizon, samples, 60);
}

double firstScanned(const std::function<bool(double)>& holds, double end, int samples,
                    int bisections) {
  if (holds(0.0)) return 0.0;
  double prev = 0.0;
  for (int i = 1; i <= samples; ++i) {
    const double t = end * i / samples;
    if (holds(t)) {
      double lo = prev, hi = t;
      for (int k = 0; k < bisections; ++k) {
        const double mid = 0.5 * (lo + hi);
        (holds(mid) ? hi : lo) = mid;
      }
      return hi;
    }
    prev = t;
  }
  return -1.0;
}

// The first contact of any pair of the scene under `twist`, scanned; -1 when none.
double scannedSceneContact(const PathScene& scene, const Twist& twist, double horizon,
                           int samples) {
  double first = -1.0;
  for (const NamedEllipse& link : scene.links) {
    for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
      if (scene.allowed.contains(link.name, scene.obstacles[o].name)) continue;
      const double t = scannedContact(link.ellipse, twist, scene.obstacles[o].ellipse,
                                      scene.obstacle_motions[o], horizon, samples);
      if (t >= 0.0 && (first < 0.0 || t < first)) first = t;
    }
  }
  return first;
}

}  // namespace ellipse_collision::core::twist_oracle
