#include "ellipse_collision/app/scan_name_keeper.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <unordered_set>

namespace ellipse_collision::app {
namespace {

/// The keys of `span` as at most two plain intervals [first, last] of a ring of `ring` keys.
struct Intervals {
  std::array<std::pair<std::size_t, std::size_t>, 2> interval;
  std::size_t count;
  const std::pair<std::size_t, std::size_t>* begin() const { return interval.data(); }
  const std::pair<std::size_t, std::size_t>* end() const { return interval.data() + count; }
};
Intervals intervals(const KeySpan& span, std::size_t ring) {
  if (span.first <= span.last) return {{{{span.first, span.last}, {0, 0}}}, 1};
  return {{{{span.first, ring - 1}, {0, span.last}}}, 2};
}

std::size_t length(const KeySpan& span, std::size_t ring) {
  return span.first <= span.last ? span.last - span.first + 1 : ring - span.first + span.last + 1;
}

}  // namespace

std::size_t sharedKeys(const KeySpan& a, const KeySpan& b, std::size_t ring) {
  std::size_t shared = 0;
  for (const auto& [a_first, a_last] : intervals(a, ring)) {
    for (const auto& [b_first, b_last] : intervals(b, ring)) {
      const std::size_t first = std::max(a_first, b_first), last = std::min(a_last, b_last);
      if (first <= last) shared += last - first + 1;
    }
  }
  return shared;
}

void ScanNameKeeper::rename(SensorObstacles& obstacles) {
  std::vector<EllipseSpec>& ellipses = obstacles.ellipses;
  const std::size_t ring = obstacles.key_ring;
  const std::size_t count = std::min(ellipses.size(), obstacles.spans.size());
  const std::string frame_id = ellipses.empty() ? frame_id_ : ellipses.front().frame_id;
  if (ring != key_ring_ || frame_id != frame_id_) {
    last_.clear();
    gone_.clear();
  }
  key_ring_ = ring;
  frame_id_ = frame_id;
  ++message_;

  std::vector<char> named(ellipses.size(), 0);
  std::unordered_set<std::string> used;
  // Matches the ellipses not yet named against `earlier`; returns which of those were taken.
  const auto match = [&](const std::vector<Named>& earlier) {
    // Candidate pairs (shared keys, new index, old index), most shared first; ties by index, so
    // the result depends on nothing but the messages.
    std::vector<std::tuple<std::size_t, std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < count; ++i) {
      if (named[i]) continue;
      const KeySpan& now = obstacles.spans[i];
      for (std::size_t j = 0; j < earlier.size(); ++j) {
        const std::size_t shared = sharedKeys(now, earlier[j].span, ring);
        const std::size_t shorter = std::min(length(now, ring), length(earlier[j].span, ring));
        if (2 * shared > shorter) pairs.emplace_back(shared, i, j);
      }
    }
    std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
      if (std::get<0>(a) != std::get<0>(b)) return std::get<0>(a) > std::get<0>(b);
      return std::make_pair(std::get<1>(a), std::get<2>(a)) <
             std::make_pair(std::get<1>(b), std::get<2>(b));
    });
    std::vector<char> taken(earlier.size(), 0);
    for (const auto& [shared, i, j] : pairs) {
      if (named[i] || taken[j]) continue;
      named[i] = taken[j] = 1;
      ellipses[i].name = earlier[j].name;
      used.insert(ellipses[i].name);
    }
    return taken;
  };
  const std::vector<char> kept = match(last_);
  const std::vector<char> back = match(gone_);
  for (std::size_t i = 0; i < ellipses.size(); ++i) {
    if (named[i]) continue;
    const std::string base = ellipses[i].name;
    for (int n = 2; used.count(ellipses[i].name); ++n) {
      ellipses[i].name = base + "_" + std::to_string(n);
    }
    used.insert(ellipses[i].name);
  }

  // What went away now joins the remembered; what came back or is too old leaves them; a name
  // in use now is never remembered as gone.
  dropped_ = 0;
  std::vector<Named> gone;
  for (std::size_t j = 0; j < gone_.size(); ++j) {
    if (!back[j] && message_ - gone_[j].message <= kRememberedMessages &&
        !used.count(gone_[j].name)) {
      gone.push_back(gone_[j]);
    }
  }
  for (std::size_t j = 0; j < last_.size(); ++j) {
    if (kept[j]) continue;
    ++dropped_;
    if (!used.count(last_[j].name)) gone.push_back(last_[j]);
  }
  gone_ = std::move(gone);
  last_.clear();
  for (std::size_t i = 0; i < count; ++i) {
    last_.push_back({ellipses[i].name, obstacles.spans[i], message_});
  }
}

}  // namespace ellipse_collision::app
