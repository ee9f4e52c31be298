#include "ellipse_collision/app/frame_placer.h"

#include <utility>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

FramePlacer::FramePlacer(TransformLookup lookup, double global_padding_m, Freshness freshness)
    : lookup_(std::move(lookup)), global_padding_m_(global_padding_m), freshness_(freshness) {}

const FrameTransform& FramePlacer::lookup(const std::string& frame) {
  const auto cached = frames_.find(frame);
  if (cached != frames_.end()) return cached->second;
  return frames_.emplace(frame, lookup_(frame)).first->second;
}

FramePlacer::Placement FramePlacer::place(const EllipseSpec& spec, core::EllipseRole role) {
  Placement placement;
  placement.ellipse.name = spec.name;
  placement.ellipse.role = role;
  const FrameTransform& frame = lookup(spec.frame_id);
  if (!frame.ok) {
    placement.status = Status::FrameUnavailable;
    placement.error = frame.error;
    return placement;
  }
  if (isStale(frame, freshness_)) {
    placement.status = Status::Stale;
    placement.age_s = ageOf(frame, freshness_);
    placement.error =
        "transform of frame '" + spec.frame_id + "' is " + core::formatNumber(placement.age_s) +
        " s old, older than max_transform_age " + core::formatNumber(freshness_.max_age_s) + " s";
    return placement;
  }
  const core::ProjectionResult projected =
      placeInPlane(spec, global_padding_m_, frame.fixed_from_frame);
  if (!projected.ok()) {
    placement.status = Status::Degenerate;
    placement.error = projected.error;
    return placement;
  }
  placement.ellipse.ellipse = projected.ellipse;
  return placement;
}

}  // namespace ellipse_collision::app
