#pragma once

#include <quadmath.h>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"

namespace ellipse_collision::core {
namespace test {

/// The first contact of two moving ellipses computed independently of firstContact(), in quad
/// precision, on the primal side: the boundary of the Minkowski sum K = A + B of the centred
/// ellipses is traced as k(phi) = s_A(u) + s_B(u) (s the support point of direction
/// u = (cos phi, sin phi)), and
///  - the gauge of K at a point p is |p|^2 / (p . k) at the phi where k(phi) lies on the ray of p
///    (bisection of a monotone arc of the boundary);
///  - under translation the first contact is where the line p0 + w t enters K (bisection on the
///    two arcs between the extreme points of K normal to w), and the minimum gauge along the line
///    is |n . p0| / h_K(n) in closed form (n normal to w), clipped to [0, horizon];
///  - under rotation the gauge is scanned on a dense time grid in long double and the first
///    crossing is bisected in quad (a contact shorter than horizon / samples may be missed).
struct OracleFirstContact {
  bool contact{false};
  __float128 time{0};       ///< first contact [s]; 0 when none
  __float128 min_scale{0};  ///< smallest contact scale over [0, horizon] (approximate for rotation)
  /// Translation with contact after 0: |cos| of the angle between the relative path and the outer
  /// normal of K at the entry point (1 head-on, towards 0 as the path grazes K's boundary); the
  /// entry time's sensitivity to a shift of the path across itself grows as its inverse. 1 else.
  __float128 entry_cosine{1};
};

OracleFirstContact oracleFirstContact(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                                      const Motion& motion_b, double horizon,
                                      int rotation_samples = 2000);

/// Contact scale of the pair at time t, in quad precision (the boundary gauge above).
__float128 oracleScaleAt(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                         const Motion& motion_b, __float128 t);

/// A rigid planar motion in quad precision, more general than Motion: the centre at
///   c(t) = c0 + v t + (sin(W t) u + (1 - cos(W t)) u_perp) / W    (u_perp: u turned +90 deg)
/// (a constant velocity v plus a velocity u, at t = 0, that turns at W: the centre on an arc about
/// a point that moves at v), the angle at angle0 + W t. A Motion {v, w} is u = 0, W = w; a body
/// fixed to a frame turning at W (a twist, a turning path segment) has u = W z x (c0 - pivot).
struct OracleRigidMotion {
  __float128 x{0}, y{0}, angle{0};  ///< c0 [m], angle0 [rad]
  __float128 vx{0}, vy{0};          ///< v [m/s]
  __float128 ux{0}, uy{0};          ///< u [m/s]
  __float128 turn_rate{0};          ///< W [rad/s]
};

/// `e` (centre, angle) moving by `m`.
OracleRigidMotion oracleMotionOf(const Ellipse& e, const Motion& m);

/// Contact scale at t of two ellipses with the radii of `a` and `b` (their centres and angles are
/// taken from `motion_a` and `motion_b`), in quad precision (the boundary gauge above).
__float128 oracleRigidScaleAt(const Ellipse& a, const OracleRigidMotion& motion_a, const Ellipse& b,
                              const OracleRigidMotion& motion_b, __float128 t);

/// `e`'s radii at the centre and angle of `motion` at time t, rounded to double.
Ellipse oraclePoseAt(const Ellipse& e, const OracleRigidMotion& motion, __float128 t);

/// The velocity of `motion`'s centre at time t [m/s], rounded to double.
Eigen::Vector2d oracleVelocityAt(const OracleRigidMotion& motion, __float128 t);

/// A pass made to graze (see oracleGrazingPass()).
struct OracleGrazingPass {
  bool found{false};           ///< false: the pass is not a single dip inside [0, horizon]
  __float128 time{0};          ///< of the smallest contact scale [s]
  __float128 scale{0};         ///< the smallest contact scale, after the radii were scaled
  bool contact{false};         ///< scale <= 1
  __float128 contact_time{0};  ///< the first contact [s] when `contact`
};

/// Scales the radii of `a` and `b` alike so that the smallest contact scale of the pair over
/// [0, horizon] becomes `target` (the gauge of the Minkowski sum is inversely proportional to a
/// common scale of both ellipses, while the motions stay). The scale is scanned on `samples`
/// intervals in long double; the pass must fall at every sample up to its smallest and rise at
/// every one after it, inside the interval (else nothing is changed and `found` is false). The
/// smallest is refined by golden section in quad, and the first contact bisected in quad on
/// [0, time] (a single crossing: the scale falls there).
OracleGrazingPass oracleGrazingPass(Ellipse& a, const OracleRigidMotion& motion_a, Ellipse& b,
                                    const OracleRigidMotion& motion_b, double horizon,
                                    double target, int samples = 400);

}  // namespace test
}  // namespace ellipse_collision::core
