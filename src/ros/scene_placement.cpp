#include "ellipse_collision/ros/scene_placement.h"

#include <utility>

#include "ellipse_collision/core/frame_projection.h"
#include "ellipse_collision/ros/tf_lookup.h"

namespace ellipse_collision {

ScenePlacement::ScenePlacement(const tf2_ros::Buffer& buffer, std::string fixed_frame,
                               double global_padding_m, ros::Time time, ros::Duration timeout)
    : buffer_(buffer),
      fixed_frame_(std::move(fixed_frame)),
      global_padding_m_(global_padding_m),
      time_(time),
      timeout_(timeout) {}

const ScenePlacement::FrameLookup& ScenePlacement::lookup(const std::string& frame) {
  const auto cached = frames_.find(frame);
  if (cached != frames_.end()) return cached->second;
  FrameLookup result;
  result.ok = lookupTransformSafe(buffer_, fixed_frame_, frame, time_, timeout_,
                                  result.fixed_from_frame, &result.error);
  return frames_.emplace(frame, result).first->second;
}

ScenePlacement::Placement ScenePlacement::place(const EllipseSpec& spec, core::EllipseRole role) {
  Placement placement;
  placement.ellipse.name = spec.name;
  placement.ellipse.role = role;
  const FrameLookup& frame = lookup(spec.frame_id);
  if (!frame.ok) {
    placement.status = Status::FrameUnavailable;
    placement.error = frame.error;
    return placement;
  }
  const core::ProjectionResult projected =
      core::projectToPlane(paddedEllipse(spec, global_padding_m_), frame.fixed_from_frame, spec.name);
  if (!projected.ok()) {
    placement.status = Status::Degenerate;
    placement.error = projected.error;
    return placement;
  }
  placement.ellipse.ellipse = projected.ellipse;
  return placement;
}

}  // namespace ellipse_collision
