#include "pair_culling.h"

#include <cstring>

#include "ellipse_collision/core/overlap.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define ELLIPSE_COLLISION_X86_64_KERNELS 1
#include <immintrin.h>
#endif

namespace ellipse_collision::core::detail {
namespace {

/// Pairs [begin, end): the two circle tests of overlap() (overlap.h, and the inscribed circles
/// of its exact stages, overlap.cpp) with the same operations in the same order, so with the same
/// bits: out[k] = 1 where the inscribed circles prove overlap, 0 where the bounding circles prove
/// separation or where it is left open; the pairs left open are listed in `survivors`, their
/// number returned. Without a branch per pair: a far pair and a near one cost the same. For one
/// ellipse against many (kOneToMany), the `a` side holds one ellipse, read at index 0 for every
/// pair.
template <bool kOneToMany>
std::size_t cullPortable(CullColumns a, CullColumns b, std::size_t begin, std::size_t end,
                         std::uint8_t* out, std::size_t* survivors) {
  std::size_t kept = 0;
  for (std::size_t k = begin; k < end; ++k) {
    const std::size_t ka = kOneToMany ? 0 : k;
    const double dx = b.x[k] - a.x[ka];
    const double dy = b.y[k] - a.y[ka];
    const double squared_distance = dx * dx + dy * dy;
    const double reach = a.bounding[ka] + b.bounding[k];
    const double inner = a.inscribed[ka] + b.inscribed[k];
    const bool apart = squared_distance > reach * reach * (1.0 + kCircleMargin);
    const bool inside = squared_distance < inner * inner * (1.0 - kCircleMargin);
    out[k] = static_cast<std::uint8_t>(inside);
    survivors[kept] = k;
    kept += static_cast<std::size_t>(!(apart | inside));
  }
  return kept;
}

#ifdef ELLIPSE_COLLISION_X86_64_KERNELS
/// cullPortable() two pairs at a time in SSE2 registers, which every x86-64 processor has: the
/// same operations on each lane, so the same bits. The remainder goes through cullPortable().
template <bool kOneToMany>
std::size_t cullSse2(CullColumns a, CullColumns b, std::size_t begin, std::size_t end,
                     std::uint8_t* out, std::size_t* survivors) {
  const __m128d grow = _mm_set1_pd(1.0 + kCircleMargin);
  const __m128d shrink = _mm_set1_pd(1.0 - kCircleMargin);
  // The one ellipse of a one-to-many batch, loaded once: the byte stores to `out` may alias
  // anything, so a load inside the loop would be repeated on every step.
  const auto one = [](const double* column) {
    return kOneToMany ? _mm_load1_pd(column) : _mm_setzero_pd();
  };
  const __m128d one_x = one(a.x), one_y = one(a.y);
  const __m128d one_bounding = one(a.bounding), one_inscribed = one(a.inscribed);
  const auto load_a = [](__m128d one, const double* column, std::size_t k) {
    return kOneToMany ? one : _mm_loadu_pd(column + k);
  };
  std::size_t kept = 0;
  std::size_t k = begin;
  for (; k + 2 <= end; k += 2) {
    const __m128d dx = _mm_sub_pd(_mm_loadu_pd(b.x + k), load_a(one_x, a.x, k));
    const __m128d dy = _mm_sub_pd(_mm_loadu_pd(b.y + k), load_a(one_y, a.y, k));
    const __m128d squared_distance = _mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy));
    const __m128d reach =
        _mm_add_pd(load_a(one_bounding, a.bounding, k), _mm_loadu_pd(b.bounding + k));
    const __m128d inner =
        _mm_add_pd(load_a(one_inscribed, a.inscribed, k), _mm_loadu_pd(b.inscribed + k));
    const int apart =
        _mm_movemask_pd(_mm_cmpgt_pd(squared_distance, _mm_mul_pd(_mm_mul_pd(reach, reach), grow)));
    const int inside = _mm_movemask_pd(
        _mm_cmplt_pd(squared_distance, _mm_mul_pd(_mm_mul_pd(inner, inner), shrink)));
    out[k] = static_cast<std::uint8_t>(inside & 1);
    out[k + 1] = static_cast<std::uint8_t>(inside >> 1);
    const int open = ~(apart | inside) & 0x3;
    if (open != 0) {  // as in cullAvx2()
      survivors[kept] = k;
      kept += static_cast<std::size_t>(open & 1);
      survivors[kept] = k + 1;
      kept += static_cast<std::size_t>(open >> 1);
    }
  }
  return kept + cullPortable<kOneToMany>(a, b, k, end, out, survivors + kept);
}

/// The bytes 0 or 1 of four pairs from the four bits of a comparison mask, little-endian.
constexpr std::uint32_t maskBytes(int mask) {
  return static_cast<std::uint32_t>((mask & 1) | ((mask >> 1) & 1) << 8 | ((mask >> 2) & 1) << 16 |
                                    ((mask >> 3) & 1) << 24);
}

/// The one ellipse's value of a column four times, or nothing to read (pairs i-i).
template <bool kOneToMany>
__attribute__((target("avx2"))) inline __m256d oneOf(const double* column) {
  return kOneToMany ? _mm256_broadcast_sd(column) : _mm256_setzero_pd();
}

/// Four values of a column of the `a` side from pair k on, or `one`, its one ellipse's value
/// four times (loaded once, as in cullSse2()).
template <bool kOneToMany>
__attribute__((target("avx2"))) inline __m256d loadA(__m256d one, const double* column,
                                                     std::size_t k) {
  return kOneToMany ? one : _mm256_loadu_pd(column + k);
}

/// cullPortable() four pairs at a time in AVX2 registers: the same multiplications, additions
/// and comparisons on each lane (no fused multiply-add: target "avx2" alone does not enable FMA,
/// which would round differently), so the same bits. The remainder goes through cullPortable().
template <bool kOneToMany>
__attribute__((target("avx2"))) std::size_t cullAvx2(CullColumns a, CullColumns b,
                                                     std::size_t begin, std::size_t end,
                                                     std::uint8_t* out, std::size_t* survivors) {
  const __m256d grow = _mm256_set1_pd(1.0 + kCircleMargin);
  const __m256d shrink = _mm256_set1_pd(1.0 - kCircleMargin);
  const __m256d one_x = oneOf<kOneToMany>(a.x), one_y = oneOf<kOneToMany>(a.y);
  const __m256d one_bounding = oneOf<kOneToMany>(a.bounding);
  const __m256d one_inscribed = oneOf<kOneToMany>(a.inscribed);
  std::size_t kept = 0;
  std::size_t k = begin;
  for (; k + 4 <= end; k += 4) {
    const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(b.x + k), loadA<kOneToMany>(one_x, a.x, k));
    const __m256d dy = _mm256_sub_pd(_mm256_loadu_pd(b.y + k), loadA<kOneToMany>(one_y, a.y, k));
    const __m256d squared_distance = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    const __m256d reach = _mm256_add_pd(loadA<kOneToMany>(one_bounding, a.bounding, k),
                                        _mm256_loadu_pd(b.bounding + k));
    const __m256d inner = _mm256_add_pd(loadA<kOneToMany>(one_inscribed, a.inscribed, k),
                                        _mm256_loadu_pd(b.inscribed + k));
    const int apart = _mm256_movemask_pd(_mm256_cmp_pd(
        squared_distance, _mm256_mul_pd(_mm256_mul_pd(reach, reach), grow), _CMP_GT_OQ));
    const int inside = _mm256_movemask_pd(_mm256_cmp_pd(
        squared_distance, _mm256_mul_pd(_mm256_mul_pd(inner, inner), shrink), _CMP_LT_OQ));
    const std::uint32_t bytes = maskBytes(inside);
    std::memcpy(out + k, &bytes, sizeof bytes);
    // All four written, each kept only if open: no branch per pair. The one branch per four
    // is rarely taken in a scene (most pairs far apart) and mostly taken among near pairs, so
    // either way well predicted.
    const int open = ~(apart | inside) & 0xF;
    if (open != 0) {
      for (int lane = 0; lane < 4; ++lane) {
        survivors[kept] = k + lane;
        kept += static_cast<std::size_t>((open >> lane) & 1);
      }
    }
  }
  // The exact stages that follow are SSE code: with the upper halves of the registers left
  // dirty, every SSE instruction there would pay for merging them (GCC 12 did not always clear
  // them itself: the pairs i-i were 50 % slower than with the portable culling).
  _mm256_zeroupper();
  return kept + cullPortable<kOneToMany>(a, b, k, end, out, survivors + kept);
}
#endif

template <bool kOneToMany>
std::size_t cull(bool avx2, const CullColumns& a, const CullColumns& b, std::size_t begin,
                 std::size_t end, std::uint8_t* out, std::size_t* survivors) {
#ifdef ELLIPSE_COLLISION_X86_64_KERNELS
  return avx2 ? cullAvx2<kOneToMany>(a, b, begin, end, out, survivors)
              : cullSse2<kOneToMany>(a, b, begin, end, out, survivors);
#else
  static_cast<void>(avx2);
  return cullPortable<kOneToMany>(a, b, begin, end, out, survivors);
#endif
}

}  // namespace

bool avx2Supported() {
#ifdef ELLIPSE_COLLISION_X86_64_KERNELS
  static const bool supported = __builtin_cpu_supports("avx2");
  return supported;
#else
  return false;
#endif
}

bool useAvx2(BatchKernel kernel) { return kernel != BatchKernel::Portable && avx2Supported(); }

std::size_t cullPairs(bool avx2, const CullColumns& a, const CullColumns& b, std::size_t begin,
                      std::size_t end, std::uint8_t* out, std::size_t* survivors) {
  return cull<false>(avx2, a, b, begin, end, out, survivors);
}

std::size_t cullOneAgainstMany(bool avx2, const CullColumns& one, const CullColumns& b,
                               std::size_t begin, std::size_t end, std::uint8_t* out,
                               std::size_t* survivors) {
  return cull<true>(avx2, one, b, begin, end, out, survivors);
}

}  // namespace ellipse_collision::core::detail
