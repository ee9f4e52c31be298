// Fuzz target: one pair of ellipses through every stage of the core (validation, the polygonal
// test, the eigenvalue test, contactScale, overlap, distance). Fields are arbitrary doubles:
// NaN, inf, subnormals, 1e300, range edges, raw bit patterns (see fuzz_input.h).
//
// Invariants:
//  - invalidReason() agrees with the documented rule (ellipse.h) and names a field; an invalid
//    pair is refused by checkScene() before any arithmetic. The stages themselves require valid
//    input (ellipse.h), so only valid pairs reach them; there NaN cannot arise, and subnormal
//    centres, 1e300 or DBL_MAX angles and the range edges still do;
//  - every stage is exactly symmetric in (a, b): same bits, not just close;
//  - contactScale is finite and >= 0, within 1e-12 of the certified maximisation of Q behind its
//    quartic (axis ratios to 1e9), and overlap iff contactScale <= 1 outside a tiny band
//    around 1 (see kTangencyBand); each stage's certified answer agrees with it;
//  - halving both radii doubles the contact scale (t* is homogeneous), so overlap of the halved
//    pair implies overlap of the original;
//  - distance() reports separation exactly when overlap() does not;
//  - the batch tests (overlapBatch(), overlapOneToMany()) answer every pair as overlap() does,
//    with the portable and, where the processor has it, the AVX2 culling, the pair in every
//    lane of their registers and in their scalar remainder.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "ellipse_collision/core/batch_overlap.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/ellipse_collision.h"
#include "ellipse_collision/core/scene_check.h"
#include "contact_scale_detail.h"
#include "fuzz_input.h"
#include "relative_shape.h"

namespace ellipse_collision::fuzz {
namespace {

// overlap() decides by certified bounds, contactScale() converges to ~1e-15 relative but is only
// claimed accurate to 1e-9 (test_overlap_accuracy.cpp): within that band of exact tangency the
// two may legitimately disagree by rounding, so the comparison is only made outside it.
constexpr double kTangencyBand = 1e-9;

// contactScale() against the certified maximisation of Q (see checkValidPair()).
constexpr double kQuarticAgreement = 1e-12;
constexpr double kConditionedAxisRatio = 1e9;
constexpr double kUnderflowScale = 1e-290;

double axisRatio(const core::Ellipse& e) {
  return std::max(e.radius_x, e.radius_y) / std::min(e.radius_x, e.radius_y);
}

bool sameBits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

std::string pairText(const core::Ellipse& a, const core::Ellipse& b) {
  return "a = " + describe(a) + ", b = " + describe(b);
}

void checkValidation(const core::Ellipse& e) {
  const std::string reason = core::invalidReason(e);
  FUZZ_REQUIRE(
      reason.empty() == documentedValid(e),
      "invalidReason disagrees with the documented rule for " + describe(e) + ": '" + reason + "'");
  if (!reason.empty()) {
    const bool names_field = reason.rfind("center.x", 0) == 0 || reason.rfind("center.y", 0) == 0 ||
                             reason.rfind("radius_x", 0) == 0 || reason.rfind("radius_y", 0) == 0 ||
                             reason.rfind("angle", 0) == 0;
    FUZZ_REQUIRE(names_field, "invalidReason does not start with a field name: '" + reason + "'");
  }
}

void checkInvalidPairIsRefused(const core::Ellipse& a, const core::Ellipse& b) {
  const core::SceneCheckResult result =
      core::checkScene({{"a", core::EllipseRole::Link, a}, {"b", core::EllipseRole::Obstacle, b}}, core::SceneRules{});
  FUZZ_REQUIRE(!result.ok() && result.collisions.empty(),
               "checkScene accepted an invalid pair " + pairText(a, b));
  const std::string& bad_name = core::invalidReason(a).empty() ? "'b'" : "'a'";
  FUZZ_REQUIRE(result.error.find(bad_name) != std::string::npos,
               "checkScene error does not name the invalid entry: " + result.error);
}

void checkValidPair(const core::Ellipse& a, const core::Ellipse& b, int polygonal_iterations) {
  const double t = core::contactScale(a, b);
  FUZZ_REQUIRE(sameBits(t, core::contactScale(b, a)), "contactScale not symmetric: " + pairText(a, b));
  FUZZ_REQUIRE(std::isfinite(t) && t >= 0.0,
               "contactScale = " + text(t) + " is not finite and >= 0: " + pairText(a, b));
  // contactScale() solves a quartic and falls back to the certified maximisation of Q only when
  // that is not done in time: the two must agree within what firstContact() allows for its
  // rounding (kScaleRounding, 2.5e-12). Beyond kConditionedAxisRatio the relative frame both
  // are built on cancels digits (a needle along the offset: both 1e-8 off the quad oracle).
  if (axisRatio(a) <= kConditionedAxisRatio && axisRatio(b) <= kConditionedAxisRatio) {
    const double certified = core::detail::contactScalePrincipal(
        core::detail::principalShape(core::detail::canonicalRelativeShape(a, b)));
    // Subnormal centre offsets: the certified path's products underflow to t* = 0 (the quartic
    // keeps ~1e-309); both mean "coincident" to every decision.
    FUZZ_REQUIRE(std::fabs(t - certified) <= kQuarticAgreement * certified ||
                     std::max(t, certified) < kUnderflowScale,
                 "contactScale = " + text(t) + " but the certified maximisation gives " +
                     text(certified) + ": " + pairText(a, b));
  }
  const bool clearly_overlapping = t < 1.0 - kTangencyBand;
  const bool clearly_separate = t > 1.0 + kTangencyBand;

  const bool overlapping = core::overlap(a, b);
  FUZZ_REQUIRE(overlapping == core::overlap(b, a), "overlap not symmetric: " + pairText(a, b));
  FUZZ_REQUIRE(!(clearly_overlapping && !overlapping) && !(clearly_separate && overlapping),
               "overlap = " + std::string(overlapping ? "true" : "false") +
                   " but contactScale = " + text(t) + ": " + pairText(a, b));

  const bool eigen = core::eigenvalueOverlap(a, b);
  FUZZ_REQUIRE(eigen == core::eigenvalueOverlap(b, a),
               "eigenvalueOverlap not symmetric: " + pairText(a, b));
  FUZZ_REQUIRE(!(clearly_overlapping && !eigen) && !(clearly_separate && eigen),
               "eigenvalueOverlap = " + std::string(eigen ? "true" : "false") +
                   " but contactScale = " + text(t) + ": " + pairText(a, b));

  const core::PolygonalResult polygonal = core::polygonalTest(a, b, polygonal_iterations);
  FUZZ_REQUIRE(polygonal == core::polygonalTest(b, a, polygonal_iterations),
               "polygonalTest not symmetric: " + pairText(a, b));
  FUZZ_REQUIRE(!(clearly_overlapping && polygonal == core::PolygonalResult::Separate) &&
                   !(clearly_separate && polygonal == core::PolygonalResult::Overlap),
               std::string("polygonalTest = ") + toString(polygonal) + " (iterations " +
                   std::to_string(polygonal_iterations) + ") but contactScale = " + text(t) + ": " +
                   pairText(a, b));

  // t* is homogeneous of degree -1 in the radii; halving is exact in binary. Below t ~ 1e-100
  // the squared offsets inside the eigenvalue test reach the subnormal range and lose relative
  // precision, which no overlap decision can notice, so the check stops there.
  core::Ellipse half_a = a, half_b = b;
  half_a.radius_x /= 2, half_a.radius_y /= 2, half_b.radius_x /= 2, half_b.radius_y /= 2;
  if (documentedValid(half_a) && documentedValid(half_b) && t > 1e-100) {
    const double t_half = core::contactScale(half_a, half_b);
    FUZZ_REQUIRE(std::fabs(t_half - 2.0 * t) <= kTangencyBand * 2.0 * t,
                 "contactScale of the halved pair " + text(t_half) + " is not twice " + text(t) +
                     ": " + pairText(a, b));
    FUZZ_REQUIRE(!core::overlap(half_a, half_b) || overlapping,
                 "halved pair overlaps but the original does not: " + pairText(a, b));
  }

  const core::Clearance clearance = core::distance(a, b);
  FUZZ_REQUIRE(clearance.separated == !overlapping,
               "distance().separated disagrees with overlap(): " + pairText(a, b));
  FUZZ_REQUIRE(std::isfinite(clearance.distance) && clearance.distance >= 0.0 &&
                   clearance.point_a.allFinite() && clearance.point_b.allFinite(),
               "distance() returned a non-finite or negative result: " + pairText(a, b));
}

/// The pairs (a, b), (b, a), (a, a), (b, b), (a, b) through the batch tests: five, so that the
/// AVX2 culling takes the first four in one register and the fifth in its remainder, and the
/// SSE2 culling two, two and one.
void checkBatchAgrees(const core::Ellipse& a, const core::Ellipse& b) {
  const core::Ellipse firsts[] = {a, b, a, b, a};
  const core::Ellipse seconds[] = {b, a, a, b, b};
  core::EllipseBatch first_batch, second_batch;
  for (int k = 0; k < 5; ++k) {
    FUZZ_REQUIRE(first_batch.add(firsts[k]).empty() && second_batch.add(seconds[k]).empty(),
                 "EllipseBatch refused a valid ellipse: " + pairText(a, b));
  }
  std::vector<core::detail::BatchKernel> kernels{core::detail::BatchKernel::Portable};
  if (core::detail::avx2Supported()) kernels.push_back(core::detail::BatchKernel::Avx2);
  for (const core::detail::BatchKernel kernel : kernels) {
    const std::string kernel_name =
        kernel == core::detail::BatchKernel::Avx2 ? "AVX2" : "portable";
    std::uint8_t out[5] = {7, 7, 7, 7, 7};
    core::detail::overlapBatchWith(kernel, first_batch, second_batch, out);
    for (int k = 0; k < 5; ++k) {
      FUZZ_REQUIRE(out[k] == (core::overlap(firsts[k], seconds[k]) ? 1 : 0),
                   "overlapBatch (" + kernel_name + ") disagrees with overlap() on pair " +
                       std::to_string(k) + " of " + pairText(a, b));
    }
    std::uint8_t many[5] = {7, 7, 7, 7, 7};
    core::detail::overlapOneToManyWith(kernel, core::PreparedEllipse(a), second_batch, many);
    for (int k = 0; k < 5; ++k) {
      FUZZ_REQUIRE(many[k] == (core::overlap(a, seconds[k]) ? 1 : 0),
                   "overlapOneToMany (" + kernel_name + ") disagrees with overlap() on pair " +
                       std::to_string(k) + " of " + pairText(a, b));
    }
  }
}

}  // namespace
}  // namespace ellipse_collision::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellipse_collision;
  using namespace ellipse_collision::fuzz;
  FuzzInput input(data, size);
  core::Ellipse a = input.ellipse();
  core::Ellipse b = input.ellipse();
  const int shape = input.integer(0, 3);
  // Out-of-range counts are clamped by the test; feed some to check that too.
  const int polygonal_iterations = input.integer(-2, 40);

  checkValidation(a);
  checkValidation(b);
  const bool valid = core::invalidReason(a).empty() && core::invalidReason(b).empty();
  if (!valid) {
    checkInvalidPairIsRefused(a, b);
    return 0;
  }

  // Arbitrary pairs are rarely close to touching or concentric; these shapes make them so.
  switch (shape) {
    case 1: {  // move b along the centre line to (near) exact tangency: t* is linear in it
      const double t = core::contactScale(a, b);
      if (t > 0.0) {
        core::Ellipse touching = b;
        touching.center = a.center + (b.center - a.center) / t;
        if (core::invalidReason(touching).empty()) b = touching;
      }
      break;
    }
    case 2:
      b.center = a.center;  // concentric: t* = 0
      break;
    case 3:
      b.radius_x = a.radius_x, b.radius_y = a.radius_y;  // congruent shapes
      break;
    default:
      break;
  }
  checkValidPair(a, b, polygonal_iterations);
  checkBatchAgrees(a, b);
  if (shape == 2) {
    FUZZ_REQUIRE(
        core::contactScale(a, b) == 0.0 && core::overlap(a, b),
        "concentric pair must overlap with contact scale 0: " + describe(a) + ", " + describe(b));
  }
  return 0;
}
