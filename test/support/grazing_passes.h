#pragma once

// Turning passes for the first-contact tests and bench_first_contact (firstContact(),
// twistContact(), segmentContact()): an obstacle placed against a moving link in the middle of its
// pass, the pair then made to pass at a chosen smallest contact scale by oracleGrazingPass()
// (first_contact_oracle.h), whose first contact is the reference.
#include <cstdio>
#include <initializer_list>
#include <string>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/path_motion.h"
#include "ellipse_collision/core/twist_motion.h"
#include "first_contact_oracle.h"
#include "random_source.h"

namespace ellipse_collision::core::test {

/// The depths (1 - smallest contact scale) of the passes, either side of touching, in turn.
inline constexpr double kGrazingDepths[] = {1e-8, 1e-10, 1e-12};

/// A turning pass: `a` (a link) moving by `motion_a` (firstContact()), `twist` (twistContact())
/// or `segment` (segmentContact(), `a` in the moving frame), `b` (an obstacle) by `motion_b`,
/// scaled by oracleGrazingPass() to pass at a chosen smallest contact scale.
struct TurningPass {
  Ellipse a, b;
  Motion motion_a, motion_b;
  Twist twist;
  SegmentMotion segment;
  double horizon{1.0};
  OracleGrazingPass pass;
  /// The numbers that make the pass, to 17 digits (exactNumbers()).
  std::string text;
};

// Each draws one pass at smallest contact scale `target` from `rng`: the links eccentric (axis
// ratio 3..30), the obstacles eccentric (1..20), translating and turning, the obstacle placed
// against the link at 0.3..0.7 of the horizon from across their relative velocity there. False
// when the pass is not a single dip (oracleGrazingPass()): the caller draws another.

/// Both ellipses translating and turning about their centres, horizon 1.5 s.
bool drawMotionPass(ellipse_collision::test::RandomSource& rng, double target, TurningPass* out);
/// A link offset 0.2..1.5 m from the robot frame's origin under a twist turning at 0.4..1.5
/// rad/s, so that its centre moves on an arc; horizon 1.5 s.
bool drawTwistPass(ellipse_collision::test::RandomSource& rng, double target, TurningPass* out);
/// A link offset 0.2..1.5 m from the origin of a frame up to 100 m out that drives up to 2 m and
/// turns by 0.4..3 rad over one geometric segment (duration 1).
bool drawSegmentPass(ellipse_collision::test::RandomSource& rng, double target, TurningPass* out);

/// Where two needles touch in drawNeedlePairPass(): tip to tip (the support points of a needle
/// lie near its tips for all but a sliver of directions), the flat side of a or of b against
/// the other's tip, or both flat sides facing (parallel at the pass: such passes can dip more
/// than once, finer than oracleGrazingPass() scans; placeNeedlePair() only).
enum class NeedleContact { kTips, kFlatOfA, kFlatOfB, kFlats };
/// Two needles of axis ratio `ratio` (major radius 0.2..1 m, so that the thinnest stays above
/// kMinRadius at ratio 1e8 once the pass is scaled), both translating and turning at
/// 0.4..3 rad/s, in either sense and at rates at least 0.2 rad/s apart, touching as `contact`
/// says at 0.3..0.7 of the horizon from across their relative velocity; horizon 1.5 s.
bool drawNeedlePairPass(ellipse_collision::test::RandomSource& rng, double ratio,
                        NeedleContact contact, double target, TurningPass* out);
/// The same pair placed touching at t_pass, before any scaling (no oracle, `pass` empty):
/// returns t_pass [s].
double placeNeedlePair(ellipse_collision::test::RandomSource& rng, double ratio,
                       NeedleContact contact, TurningPass* out);

/// The quad oracle's motion of a link under `twist`: the velocity v + wz z x c of its centre at
/// t = 0 turns with the frame (an arc about the instantaneous centre), and so does its angle.
OracleRigidMotion oracleTwistMotion(const Ellipse& link, const Twist& twist);

/// The quad oracle's motion of a link of a frame moving by `segment`: its centre
/// s + v tau + R(yaw0 + w tau) c is the line plus the velocity w z x R(yaw0) c at tau = 0 turning
/// at w; its angle turns at w.
OracleRigidMotion oracleSegmentMotion(const Ellipse& link_in_moving, const SegmentMotion& segment);

/// `values` to 17 significant digits, comma separated: a failing pass that can be typed back in.
inline std::string exactNumbers(std::initializer_list<double> values) {
  std::string text;
  for (const double v : values) {
    char number[32];
    std::snprintf(number, sizeof number, "%.17g", v);
    text += (text.empty() ? "" : ", ") + std::string(number);
  }
  return text;
}

}  // namespace ellipse_collision::core::test
