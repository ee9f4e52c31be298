#pragma once

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <cstddef>
#include <string>

#include "ellipse_collision/app/command_gate.h"

namespace ellipse_collision {

/// The gate's decision drawn for rviz (~gate_markers, latched): the robot's links where the
/// output command takes them at the predicted contact (or the horizon) as outlines in namespace
/// "gate_outline", coloured by the action (green PASS, yellow SLOW and ESCAPE, red otherwise);
/// the limiting obstacle outlined thick in "gate_obstacle"; the contact point in "gate_contact".
/// Ids are stable (link i is id i); what the previous array drew and this one does not is
/// DELETEd, so an rviz view never keeps a stale outline.
class GateMarkers {
 public:
  visualization_msgs::MarkerArray update(const app::GateDecision& decision,
                                         const std::string& frame_id, const ros::Time& stamp);

 private:
  std::size_t outline_count_{0};
};

}  // namespace ellipse_collision
