#pragma once

#include <cmath>
#include <cstdint>

// The reduction below rounds by adding and subtracting a constant, which -ffast-math may fold.
#ifdef __FAST_MATH__
#error "sin_cos.h needs IEEE arithmetic: build the core without -ffast-math"
#endif

namespace ellipse_collision::core::detail {

struct SinCos {
  double sin;
  double cos;
};

struct SinCosPair {
  SinCos first;
  SinCos second;
};

namespace sin_cos_detail {

using Doubles = double __attribute__((vector_size(16)));
using Bits = std::uint64_t __attribute__((vector_size(16)));

/// angle = k pi/2 + r with |r| <= pi/4. pi/2 is split into three parts (Cody and Waite): the
/// first two have 33 significant bits, so k times them is exact for |k| < 2^20, and the first
/// subtraction is exact too. Adding 1.5 * 2^52 rounds to an integer and leaves k mod 4 in the
/// lowest bits of `shifted`.
struct Reduced {
  Doubles r;
  Doubles shifted;
};

inline Reduced reduce(double angle_a, double angle_b) {
  constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
  constexpr double kHalfPiHigh = 0x1.921fb54400000p+0;
  constexpr double kHalfPiMiddle = 0x1.0b4611a600000p-34;
  constexpr double kHalfPiLow = 0x1.3198a2e037073p-69;
  constexpr double kRoundingShift = 0x1.8p52;
  const Doubles angle = {angle_a, angle_b};
  const Doubles shifted = angle * kTwoOverPi + kRoundingShift;
  const Doubles k = shifted - kRoundingShift;
  return {((angle - k * kHalfPiHigh) - k * kHalfPiMiddle) - k * kHalfPiLow, shifted};
}

/// Quadrant k mod 4: (sin, cos) = (s, c), (c, -s), (-s, -c), (-c, s), selected and negated on
/// the bits (a cast between vector types of one size keeps the bits). Angles beyond +-1e5 rad,
/// or NaN, go to the library; the other lane's result does not depend on them.
inline SinCosPair unfold(const Reduced& reduced, Doubles sin_r, Doubles cos_r, double angle_a,
                         double angle_b) {
  const Bits quadrant = (Bits)reduced.shifted & 3;
  const Bits s_bits = (Bits)sin_r;
  const Bits c_bits = (Bits)cos_r;
  const Bits swap = 0 - (quadrant & 1);
  const Bits sin_bits = ((c_bits & swap) | (s_bits & ~swap)) ^ ((quadrant & 2) << 62);
  const Bits cos_bits = ((s_bits & swap) | (c_bits & ~swap)) ^ (((quadrant + 1) & 2) << 62);
  const Doubles sin = (Doubles)sin_bits;
  const Doubles cos = (Doubles)cos_bits;
  SinCosPair result{{sin[0], cos[0]}, {sin[1], cos[1]}};

  constexpr double kFastLimit = 1e5;
  if (!(std::abs(angle_a) <= kFastLimit)) result.first = {std::sin(angle_a), std::cos(angle_a)};
  if (!(std::abs(angle_b) <= kFastLimit)) result.second = {std::sin(angle_b), std::cos(angle_b)};
  return result;
}

}  // namespace sin_cos_detail

/// sin and cos of two angles [rad] at once, within about 1 ulp. The plain overlap() needs them for
/// both ellipses of a near pair, and glibc's sincos() (which GCC fuses std::sin and std::cos into)
/// was its largest single cost: here both angles share each SSE2 instruction (GCC/Clang vector
/// extensions), the dependency chain is short, and nothing branches on the quadrant.
inline SinCosPair sinCosPair(double angle_a, double angle_b) {
  using sin_cos_detail::Doubles;
  const sin_cos_detail::Reduced reduced = sin_cos_detail::reduce(angle_a, angle_b);
  const Doubles r = reduced.r;
  // Taylor series to r^17 and r^16: the next terms are below 1e-19 for |r| <= pi/4. Estrin's
  // scheme rather than Horner's halves the dependency chain.
  const Doubles z = r * r, z2 = z * z, z4 = z2 * z2;
  const Doubles sin_tail = ((-0x1.5555555555555p-3 + 0x1.1111111111111p-7 * z) +
                            z2 * (-0x1.a01a01a01a01ap-13 + 0x1.71de3a556c734p-19 * z)) +
                           z4 * ((-0x1.ae64567f544e4p-26 + 0x1.6124613a86d09p-33 * z) +
                                 z2 * (-0x1.ae7f3e733b81fp-41 + 0x1.952c77030ad4ap-49 * z));
  const Doubles cos_tail =
      ((0x1.5555555555555p-5 - 0x1.6c16c16c16c17p-10 * z) +
       z2 * (0x1.a01a01a01a01ap-16 - 0x1.27e4fb7789f5cp-22 * z)) +
      z4 * ((0x1.1eed8eff8d898p-29 - 0x1.93974a8c07c9dp-37 * z) + z2 * 0x1.ae7f3e733b81fp-45);
  return sin_cos_detail::unfold(reduced, r + r * z * sin_tail, 1.0 - 0.5 * z + z2 * cos_tail,
                                angle_a, angle_b);
}

/// Bound on the error of sinCosPairCoarse() against the true sin and cos: the Taylor remainders
/// (pi/4)^13 / 13! < 7e-12 and (pi/4)^14 / 14! < 4e-13, plus rounding.
inline constexpr double kCoarseSinCosError = 1e-11;

/// sinCosPair() with shorter series (to r^11 and r^12), for filters whose margins allow
/// kCoarseSinCosError: about two thirds of the polynomial work.
inline SinCosPair sinCosPairCoarse(double angle_a, double angle_b) {
  using sin_cos_detail::Doubles;
  const sin_cos_detail::Reduced reduced = sin_cos_detail::reduce(angle_a, angle_b);
  const Doubles r = reduced.r;
  const Doubles z = r * r, z2 = z * z;
  const Doubles sin_tail = (-0x1.5555555555555p-3 + 0x1.1111111111111p-7 * z) +
                           z2 * ((-0x1.a01a01a01a01ap-13 + 0x1.71de3a556c734p-19 * z) +
                                 z2 * -0x1.ae64567f544e4p-26);
  const Doubles cos_tail = (0x1.5555555555555p-5 - 0x1.6c16c16c16c17p-10 * z) +
                           z2 * ((0x1.a01a01a01a01ap-16 - 0x1.27e4fb7789f5cp-22 * z) +
                                 z2 * 0x1.1eed8eff8d898p-29);
  return sin_cos_detail::unfold(reduced, r + r * z * sin_tail, 1.0 - 0.5 * z + z2 * cos_tail,
                                angle_a, angle_b);
}

/// sinCosPair() for one angle: the same instructions, hence the same bits, as in a pair.
inline SinCos sinCos(double angle) { return sinCosPair(angle, angle).first; }

}  // namespace ellipse_collision::core::detail
