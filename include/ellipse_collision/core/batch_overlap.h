#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/prepared_ellipse.h"

namespace ellipse_collision::core {

/// Ellipses stored for many pair tests at once: the centres and the bounding and inscribed radii
/// as separate arrays (structure of arrays), which the batch tests below cull in SIMD registers,
/// and each ellipse prepared (PreparedEllipse) for the exact stages of the few pairs left. Build
/// one per set of ellipses and reuse it: adding costs what preparing an ellipse costs.
class EllipseBatch {
 public:
  EllipseBatch() = default;

  /// Appends `ellipse` and returns an empty string, or, if it is invalid, appends nothing and
  /// returns invalidReason(ellipse) ("radius_x = -1 must be > 0").
  std::string add(const Ellipse& ellipse);
  void reserve(std::size_t count);
  void clear();

  std::size_t size() const { return prepared_.size(); }
  const Ellipse& ellipse(std::size_t i) const { return prepared_[i].ellipse(); }
  const PreparedEllipse& prepared(std::size_t i) const { return prepared_[i]; }

  // The columns the culling reads, one value per ellipse.
  const double* centerX() const { return center_x_.data(); }                ///< [m]
  const double* centerY() const { return center_y_.data(); }                ///< [m]
  const double* boundingRadius() const { return bounding_radius_.data(); }  ///< [m]
  const double* inscribedRadius() const { return inscribed_radius_.data(); }  ///< [m]

 private:
  std::vector<double> center_x_;
  std::vector<double> center_y_;
  std::vector<double> bounding_radius_;
  std::vector<double> inscribed_radius_;
  std::vector<PreparedEllipse> prepared_;
};

/// The pairs (a[i], b[i]): out[i] = 1 if overlap(a.ellipse(i), b.ellipse(i)), else 0, for i
/// below a.size(); `out` must hold that many bytes. The same answers as overlap() on every pair,
/// bit for bit (the culling evaluates its circle tests with the same operations in the same
/// order, and the pairs it cannot decide go through overlap()'s own exact stages). Returns an
/// empty string, or, when the sizes differ, a message naming both and writes nothing.
std::string overlapBatch(const EllipseBatch& a, const EllipseBatch& b, std::uint8_t* out);

/// One ellipse against many: out[j] = 1 if overlap(a, b.ellipse(j)), else 0, for j below
/// b.size(). Returns an empty string, or invalidReason(a) and writes nothing.
std::string overlapOneToMany(const Ellipse& a, const EllipseBatch& b, std::uint8_t* out);

namespace detail {

/// The culling code a batch test runs. Portable runs on any x86-64 processor (SSE2, two pairs at
/// a time; plain C++ on other processors); Avx2 is the same arithmetic four pairs at a time, for
/// processors that have AVX2 (Haswell, 2013, and later). Automatic picks Avx2 when the processor
/// running it has it, so one build serves both.
enum class BatchKernel { Automatic, Portable, Avx2 };

/// Whether this processor can run BatchKernel::Avx2 (always false off x86-64).
bool avx2Supported();

/// overlapBatch() of batches of equal size (unchecked) with the chosen kernel; a kernel the
/// processor lacks is replaced by Portable.
void overlapBatchWith(BatchKernel kernel, const EllipseBatch& a, const EllipseBatch& b,
                      std::uint8_t* out);

/// overlapOneToMany() of a prepared valid ellipse (unchecked) with the chosen kernel.
void overlapOneToManyWith(BatchKernel kernel, const PreparedEllipse& a, const EllipseBatch& b,
                          std::uint8_t* out);

}  // namespace detail
}  // namespace ellipse_collision::core
