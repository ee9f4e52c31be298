#include "ellipse_collision/app/gate_marker_layout.h"

namespace ellipse_collision::app {

GateMarkerLayout::Colour GateMarkerLayout::colourOf(GateAction action) {
  if (stops(action)) return {1.0f, 0.0f, 0.0f, 1.0f};
  if (action == GateAction::Slow || action == GateAction::Escape) return {1.0f, 0.8f, 0.0f, 1.0f};
  return {0.0f, 0.8f, 0.0f, 1.0f};
}

GateMarkerLayout::Drawing GateMarkerLayout::update(const GateDecision& decision) {
  Drawing drawing;
  drawing.colour = colourOf(decision.action);
  for (std::size_t i = 0; i < decision.outline.size(); ++i) {
    drawing.outlines.push_back({kOutlineNamespace, static_cast<std::int32_t>(i), true,
                                decision.outline[i].ellipse, kOutlineWidth});
  }
  for (std::size_t i = decision.outline.size(); i < outline_count_; ++i) {
    drawing.outlines.push_back(
        {kOutlineNamespace, static_cast<std::int32_t>(i), false, core::Ellipse(), kOutlineWidth});
  }
  outline_count_ = decision.outline.size();
  const bool limiting = decision.contact_predicted && !decision.obstacle.empty();
  drawing.outlines.push_back(
      {kObstacleNamespace, 0, limiting, decision.obstacle_ellipse, kObstacleWidth});
  drawing.show_contact = limiting;
  drawing.contact_point = decision.contact_point;
  return drawing;
}

}  // namespace ellipse_collision::app
