#pragma once

#include <array>
#include <cstdint>

namespace ellipse_collision::app {

/// The states an ellipse's marker shows, in rank order: an ellipse that qualifies for several
/// shows the highest. Index into kMarkerStates.
enum class MarkerState : std::uint8_t { Free, Warning, Predicted, Collision };

/// How one state is drawn. To add a state: add it to MarkerState at its rank, add its row here at
/// the same position with a new `code`, and give MarkerLayout::update() the input that puts
/// ellipses in it.
struct MarkerStateStyle {
  MarkerState state;
  const char* name;  ///< for logs and the README legend
  /// Fixed part of the state's marker ids (id = code * kIdsPerState + bucket); never reused, so
  /// a state's markers keep their ids when states are added or re-ranked.
  std::int32_t code;
  float r, g, b;  ///< colour in [0, 1]
};
inline constexpr std::array<MarkerStateStyle, 4> kMarkerStates{{
    {MarkerState::Free, "free", 0, 0.1f, 0.8f, 0.1f},            // green
    {MarkerState::Warning, "warning", 1, 0.9f, 0.85f, 0.1f},     // yellow
    {MarkerState::Predicted, "predicted", 3, 1.0f, 0.5f, 0.0f},  // orange: touches within ~prediction_horizon
    {MarkerState::Collision, "collision", 2, 0.9f, 0.1f, 0.1f},  // red
}};

/// The row of kMarkerStates that draws `state`.
inline const MarkerStateStyle& markerStyle(MarkerState state) {
  return kMarkerStates[static_cast<std::size_t>(state)];
}

}  // namespace ellipse_collision::app
