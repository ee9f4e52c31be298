#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ellipse_collision/app/velocity_gate.h"

namespace ellipse_collision::app {

/// How rviz shows a gate decision (~gate_markers), without ROS: ros::GateMarkers renders it.
/// The robot's links where the output command takes them (at the predicted contact, or the
/// horizon) as outlines in namespace "gate_outline", ids 0..n-1; the limiting obstacle outlined
/// thick in "gate_obstacle" and the contact point in "gate_contact", id 0; all in the action's
/// colour. What the previous decision drew and this one does not is deleted, so a view never
/// keeps a stale outline.
class GateMarkerLayout {
 public:
  static constexpr const char* kOutlineNamespace = "gate_outline";
  static constexpr const char* kObstacleNamespace = "gate_obstacle";
  static constexpr const char* kContactNamespace = "gate_contact";
  static constexpr double kOutlineWidth = 0.01;   ///< [m]
  static constexpr double kObstacleWidth = 0.03;  ///< [m]
  static constexpr double kContactSize = 0.08;    ///< diameter of the contact sphere [m]

  struct Colour {
    float r{0.0f}, g{0.0f}, b{0.0f}, a{1.0f};
  };
  /// One outline to show (`show`) or delete.
  struct Outline {
    const char* ns;
    std::int32_t id;
    bool show;
    core::Ellipse ellipse;
    double width;  ///< [m]
  };
  struct Drawing {
    Colour colour;
    std::vector<Outline> outlines;            ///< the links, then the limiting obstacle
    bool show_contact{false};                 ///< else delete the contact marker
    Eigen::Vector2d contact_point{0.0, 0.0};  ///< in the fixed frame [m]
  };

  /// Green for PASS and DISABLED, yellow for SLOW and ESCAPE, red for the actions that stop.
  static Colour colourOf(GateAction action);

  Drawing update(const GateDecision& decision);

 private:
  std::size_t outline_count_{0};
};

}  // namespace ellipse_collision::app
