#include "ellipse_collision/core/batch_overlap.h"

#include "ellipse_collision/core/overlap.h"
#include "pair_culling.h"

namespace ellipse_collision::core {

std::string EllipseBatch::add(const Ellipse& ellipse) {
  std::string reason = invalidReason(ellipse);
  if (!reason.empty()) return reason;
  prepared_.emplace_back(ellipse);
  const PreparedEllipse& prepared = prepared_.back();
  center_x_.push_back(ellipse.center.x());
  center_y_.push_back(ellipse.center.y());
  bounding_radius_.push_back(prepared.boundingRadius());
  inscribed_radius_.push_back(prepared.inscribedRadius());
  return reason;
}

void EllipseBatch::reserve(std::size_t count) {
  center_x_.reserve(count);
  center_y_.reserve(count);
  bounding_radius_.reserve(count);
  inscribed_radius_.reserve(count);
  prepared_.reserve(count);
}

void EllipseBatch::clear() {
  center_x_.clear();
  center_y_.clear();
  bounding_radius_.clear();
  inscribed_radius_.clear();
  prepared_.clear();
}

namespace {

/// The four columns the culling reads.
detail::CullColumns columnsOf(const EllipseBatch& batch) {
  return {batch.centerX(), batch.centerY(), batch.boundingRadius(), batch.inscribedRadius()};
}

/// The whole batch, block by block: the culling, then overlap()'s exact stages on the pairs it
/// left open. `prepared_a(k)` is the first ellipse of pair k.
template <bool kOneToMany, typename PreparedA>
void overlapAll(bool avx2, const detail::CullColumns& a, const PreparedA& prepared_a,
                const EllipseBatch& b, std::uint8_t* out) {
  const detail::CullColumns columns_b = columnsOf(b);
  std::size_t survivors[detail::kCullBlock + detail::kCullSurvivorSlack];
  for (std::size_t begin = 0; begin < b.size(); begin += detail::kCullBlock) {
    const std::size_t end =
        begin + detail::kCullBlock < b.size() ? begin + detail::kCullBlock : b.size();
    const std::size_t open =
        kOneToMany ? detail::cullOneAgainstMany(avx2, a, columns_b, begin, end, out, survivors)
                   : detail::cullPairs(avx2, a, columns_b, begin, end, out, survivors);
    for (std::size_t s = 0; s < open; ++s) {
      const std::size_t k = survivors[s];
      out[k] = static_cast<std::uint8_t>(detail::overlapOfNearPair(prepared_a(k), b.prepared(k)));
    }
  }
}

}  // namespace

namespace detail {

void overlapBatchWith(BatchKernel kernel, const EllipseBatch& a, const EllipseBatch& b,
                      std::uint8_t* out) {
  overlapAll<false>(
      detail::useAvx2(kernel), columnsOf(a),
      [&a](std::size_t k) -> const PreparedEllipse& { return a.prepared(k); }, b, out);
}

void overlapOneToManyWith(BatchKernel kernel, const PreparedEllipse& a, const EllipseBatch& b,
                          std::uint8_t* out) {
  const double x = a.ellipse().center.x();
  const double y = a.ellipse().center.y();
  const double bounding = a.boundingRadius();
  const double inscribed = a.inscribedRadius();
  overlapAll<true>(
      detail::useAvx2(kernel), detail::CullColumns{&x, &y, &bounding, &inscribed},
      [&a](std::size_t) -> const PreparedEllipse& { return a; }, b, out);
}

}  // namespace detail

std::string overlapBatch(const EllipseBatch& a, const EllipseBatch& b, std::uint8_t* out) {
  if (a.size() != b.size()) {
    return "batch sizes differ: a has " + std::to_string(a.size()) + " ellipses, b has " +
           std::to_string(b.size());
  }
  detail::overlapBatchWith(detail::BatchKernel::Automatic, a, b, out);
  return {};
}

std::string overlapOneToMany(const Ellipse& a, const EllipseBatch& b, std::uint8_t* out) {
  std::string reason = invalidReason(a);
  if (!reason.empty()) return reason;
  detail::overlapOneToManyWith(detail::BatchKernel::Automatic, PreparedEllipse(a), b, out);
  return reason;
}

}  // namespace ellipse_collision::core
