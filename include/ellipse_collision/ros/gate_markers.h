#pragma once

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "ellipse_collision/app/gate_marker_layout.h"

namespace ellipse_collision {

/// The gate's decision drawn for rviz (~gate_markers, latched): app::GateMarkerLayout's drawing
/// rendered into one MarkerArray.
class GateMarkers {
 public:
  visualization_msgs::MarkerArray update(const app::GateDecision& decision,
                                         const std::string& frame_id, const ros::Time& stamp);

 private:
  app::GateMarkerLayout layout_;
};

}  // namespace ellipse_collision
