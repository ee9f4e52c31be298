#pragma once

// The methods ours is compared against, each used the way its documentation describes.

#include <fcl/fcl.h>

#include <memory>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/path_motion.h"
#include "ellipse_collision/core/twist_motion.h"

namespace ellipse_collision::core::bench {

/// An ellipse as FCL 0.7 sees it: an Ellipsoidd(radius_x, radius_y, radius_z) at the ellipse's
/// pose. The bodies are symmetric about z = 0, so two overlap iff their sections at z = 0, the
/// ellipses, do; radius_z is therefore arbitrary (the smaller radius). Built once, outside timing.
class FclEllipse {
 public:
  explicit FclEllipse(const Ellipse& ellipse);
  const fcl::CollisionObjectd* object() const { return object_.get(); }

 private:
  std::unique_ptr<fcl::CollisionObjectd> object_;
};

/// FCL's answer for a pair: fcl::collide with a default CollisionRequestd (GJK via libccd).
bool fclCollide(const FclEllipse& a, const FclEllipse& b);

/// The method of the seed README (a demo of the eigenvalue test): the generalised eigenproblem of
/// (A^-1, B^-1) with Eigen::GeneralizedSelfAdjointEigenSolver, then gradient descent on the
/// convex K(s) from s = 0.5 with a forward-difference gradient, a fixed learning rate and an
/// iteration cap (the values of the demo's optimiser); collision iff min K >= 0.
bool seedReadmeOverlap(const Ellipse& a, const Ellipse& b);

/// firstContact() for a translating pair (angular velocities ignored) as the project computed it
/// before the Minkowski-sum entry: overlap() at t = 0, then a secant iteration from the left on the
/// convex contact scale g(t) = contactScale(a(t), b(t)), each step one contactScale() solve, with
/// a golden-section search for g's minimum and a bisection where the secant stalls (grazing). Kept
/// so that bench_first_contact times the old method beside the new one.
FirstContact secantFirstContact(const Ellipse& a, const Motion& motion_a, const Ellipse& b,
                                const Motion& motion_b, double horizon);

/// The step cap of plain conservative advancement below.
constexpr int kPlainAdvancementCap = 20000;

/// firstContact() for a rotating pair as the project computed it before the second-order steps:
/// overlap() at t = 0, then plain conservative advancement on the exact distance() in a's frame
/// (steps of D / V, a grazing band of 5e-10 (r_a + r_b), at most kPlainAdvancementCap steps,
/// contact at the last certified-safe time at the cap). `distance_calls`, when given, receives the
/// number of distance() calls. Kept so that bench_first_contact times the old method beside the
/// new one.
FirstContact plainAdvancementFirstContact(const Ellipse& a, const Motion& motion_a,
                                          const Ellipse& b, const Motion& motion_b,
                                          double horizon, int* distance_calls = nullptr);

/// twistContact() for a turning frame (wz != 0) as the project computed it before the
/// second-order steps: the same plain advancement on linkAfter() and movedBy() poses, with the
/// bound max |v_o - R(s) v_c| + |wz| (R_l - r_l) + |w_o| (R_o - r_o).
FirstContact plainAdvancementTwistContact(const Ellipse& link, const Twist& twist,
                                          const Ellipse& obstacle, const Motion& obstacle_motion,
                                          double horizon, int* distance_calls = nullptr);

/// segmentContact() for an offset link that turns, as the project computed it before the
/// second-order steps: the same plain advancement on placeAt() poses, with the bound
/// |v - v_o| + |w| |c| + |w| (R_l - r_l) + |w_o| (R_o - r_o).
FirstContact plainAdvancementSegmentContact(const Ellipse& link_in_moving,
                                            const SegmentMotion& motion, const Ellipse& obstacle,
                                            const Motion& obstacle_motion,
                                            int* distance_calls = nullptr);

}  // namespace ellipse_collision::core::bench
