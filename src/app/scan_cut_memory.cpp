#include "ellipse_collision/app/scan_cut_memory.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ellipse_collision::app {

namespace {

enum class Reading { Return, NoReturn, Unknown };

/// What a range says, as core::readBeam() would tell for any sane limits: finite and >= 0 is a
/// return, +inf none, anything else unknown.
Reading readingOf(float r) {
  if (r >= 0.0f && std::isfinite(r)) return Reading::Return;
  if (r == std::numeric_limits<float>::infinity()) return Reading::NoReturn;
  return Reading::Unknown;
}

}  // namespace

std::vector<std::size_t> ScanCutMemory::hints(const std::vector<float>& ranges,
                                              const std::string& frame_id,
                                              double range_noise_sigma) const {
  std::vector<std::size_t> keys;
  if (ranges.size() != ranges_.size() || frame_id != frame_id_ || ranges.empty()) return keys;
  const double tolerance = kSameRangeSigmas * range_noise_sigma;
  const auto same = [&](std::size_t i) {
    const Reading now = readingOf(ranges[i]);
    if (now != readingOf(ranges_[i])) return false;
    return now != Reading::Return ||
           std::abs(static_cast<double>(ranges[i]) - ranges_[i]) <= tolerance;
  };
  const std::size_t n = ranges.size();
  for (const auto& [key, unneeded] : unneeded_for_) {
    if (key < n && same(key) && same((key + n - 1) % n)) keys.push_back(key);
  }
  return keys;  // a map's keys come ascending
}

void ScanCutMemory::update(const SensorObstacles& obstacles, const std::vector<float>& ranges) {
  if (!obstacles.ellipses.empty()) frame_id_ = obstacles.ellipses.front().frame_id;
  if (ranges.size() != ranges_.size()) unneeded_for_.clear();
  ranges_ = ranges;
  std::vector<std::size_t> unneeded = obstacles.unneeded_hints;
  std::sort(unneeded.begin(), unneeded.end());
  std::map<std::size_t, std::size_t> next;
  for (const KeySpan& span : obstacles.spans) {
    std::size_t count = 0;
    if (std::binary_search(unneeded.begin(), unneeded.end(), span.first)) {
      const auto before = unneeded_for_.find(span.first);
      count = (before == unneeded_for_.end() ? 0 : before->second) + 1;
    }
    if (count < kUnneededMessages) next[span.first] = count;
  }
  unneeded_for_ = std::move(next);
}

}  // namespace ellipse_collision::app
