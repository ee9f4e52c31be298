#pragma once

#include <cstddef>
#include <cstdint>

#include "ellipse_collision/core/batch_overlap.h"

namespace ellipse_collision::core::detail {

/// The columns the culling of a pair test reads, one value per ellipse: centre x, y [m] and the
/// bounding and inscribed radii [m] (boundingRadius(), inscribedRadius() of the ellipse, which
/// PreparedEllipse holds too: max and min of its semi-axes, so equal bit for bit).
struct CullColumns {
  const double* x;
  const double* y;
  const double* bounding;
  const double* inscribed;
};

/// Whether `kernel` means the AVX2 culling on this processor (Automatic or Avx2, where
/// avx2Supported()).
bool useAvx2(BatchKernel kernel);

/// The most pairs one call of a culling should be given, so that the list of survivors stays
/// small and in the first-level cache (batch tests cull block by block).
inline constexpr std::size_t kCullBlock = 256;
/// `survivors` must hold this many entries beyond the pairs culled: the AVX2 kernel writes four
/// candidates per step, kept or not.
inline constexpr std::size_t kCullSurvivorSlack = 4;

/// The two circle tests of overlap() (overlap.h, and the inscribed circles of its exact stages,
/// overlap.cpp) on the pairs (a[k], b[k]) for k in [begin, end), with the same operations in the
/// same order, so with the same bits: out[k] = 1 where the inscribed circles prove overlap, 0 where
/// the bounding circles prove separation or where the pair is left open; the pairs left open (for
/// detail::overlapOfNearPair()) are listed in `survivors` in increasing k, their number returned.
/// Without a branch per pair. With `avx2` (only where avx2Supported()) four pairs per step, else
/// two (SSE2; one, plain C++, off x86-64): the same answers.
std::size_t cullPairs(bool avx2, const CullColumns& a, const CullColumns& b, std::size_t begin,
                      std::size_t end, std::uint8_t* out, std::size_t* survivors);

/// cullPairs() of the one ellipse of `one` (its columns read at index 0) against b[k].
std::size_t cullOneAgainstMany(bool avx2, const CullColumns& one, const CullColumns& b,
                               std::size_t begin, std::size_t end, std::uint8_t* out,
                               std::size_t* survivors);

}  // namespace ellipse_collision::core::detail
