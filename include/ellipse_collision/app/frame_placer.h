#pragma once

#include <map>
#include <string>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/transform_lookup.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::app {

/// Places ellipses attached to frames into the fixed frame's plane for one check: each frame is
/// looked up once, then the padded ellipse is projected or the padded ellipsoid's shadow cast
/// (placeInPlane()).
class FramePlacer {
 public:
  enum class Status { Placed, FrameUnavailable, Stale, Degenerate };

  struct Placement {
    Status status{Status::Placed};
    core::NamedEllipse ellipse;  ///< in the fixed frame, when Placed
    std::string error;           ///< the lookup error or the projection error otherwise
    double age_s{0.0};           ///< how old the frame's transform is [s] (when Stale)
  };

  /// `lookup` answers for the fixed frame at the check's time; global padding in [m]. A frame
  /// whose transform is stale under `freshness` (isStale()) is not placed at that old pose.
  FramePlacer(TransformLookup lookup, double global_padding_m, Freshness freshness = {});

  Placement place(const EllipseSpec& spec, core::EllipseRole role);

  /// The transform of `frame`, looked up at most once per placement.
  const FrameTransform& lookup(const std::string& frame);

  /// Every transform looked up so far, by frame, handed over (the placement then starts empty).
  std::map<std::string, FrameTransform> takeFrames() {
    std::map<std::string, FrameTransform> taken = std::move(frames_);
    frames_.clear();
    return taken;
  }
  /// Whether ellipses may be placed through `frame`: it was found and is not stale.
  bool usable(const FrameTransform& frame) const { return frame.ok && !isStale(frame, freshness_); }

 private:
  TransformLookup lookup_;
  double global_padding_m_;
  Freshness freshness_;
  std::map<std::string, FrameTransform> frames_;
};

}  // namespace ellipse_collision::app
