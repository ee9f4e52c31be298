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

}  // namespace test
}  // namespace ellipse_collision::core
