#include "ellipse_collision/app/source_freshness.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

SourceFreshness::SourceFreshness(std::vector<Source> sources) {
  for (Source& source : sources) states_.push_back(State{std::move(source), {}, 0, 0});
}

void SourceFreshness::received(std::size_t index, double now_s, std::size_t obstacles) {
  State& state = states_.at(index);
  // After a jump back of the clock the older receipts are from the future: start over.
  while (!state.received_s.empty() && state.received_s.back() > now_s) state.received_s.pop_back();
  state.received_s.push_back(now_s);
  if (state.received_s.size() > kRateWindow) state.received_s.pop_front();
  state.obstacles = obstacles;
  ++state.messages;
}

std::vector<std::string> SourceFreshness::silent(double now_s) const {
  std::vector<std::string> silent;
  for (const State& state : states_) {
    if (state.source.timeout_s <= 0.0) continue;
    const std::string name = "source '" + state.source.name + "'";
    if (state.received_s.empty()) {
      silent.push_back(name + " silent: no message yet");
      continue;
    }
    // A receipt in the future (the clock jumped back) counts as just now.
    const double age_s = std::max(0.0, now_s - state.received_s.back());
    if (age_s > state.source.timeout_s) {
      silent.push_back(name + " silent for " + core::formatNumber(std::round(age_s * 10.0) / 10.0) +
                       " s (timeout " + core::formatNumber(state.source.timeout_s) + " s)");
    }
  }
  return silent;
}

std::vector<SourceFreshness::Stats> SourceFreshness::stats(double now_s) const {
  std::vector<Stats> all;
  for (const State& state : states_) {
    Stats stats;
    stats.name = state.source.name;
    stats.obstacles = state.obstacles;
    stats.messages = state.messages;
    if (!state.received_s.empty()) {
      stats.age_s = std::max(0.0, now_s - state.received_s.back());
      const double span_s = state.received_s.back() - state.received_s.front();
      if (state.received_s.size() >= 2 && span_s > 0.0) {
        stats.rate_hz = static_cast<double>(state.received_s.size() - 1) / span_s;
      }
    }
    all.push_back(stats);
  }
  return all;
}

}  // namespace ellipse_collision::app
