#pragma once

#include <ros/duration.h>
#include <ros/time.h>
#include <tf2_ros/buffer.h>

#include <Eigen/Geometry>
#include <string>

#include "ellipse_collision/app/transform_lookup.h"

namespace ellipse_collision {

/// The node's one way to ask tf for a pose. Fills `target_from_source` and returns true, or returns
/// false with the reason in `error` (if given), which the caller reports. A frame is its own identity
/// transform even before tf has heard of it, so ellipses given in the fixed frame need no tf.
/// `time` zero means the latest transform; `timeout` is how long to wait for it. `stamp` (if
/// given) receives the transform's stamp: the latest common time of the chain, 0 for a chain of
/// static transforms looked up at time zero and for a frame looked up in itself.
bool lookupTransformSafe(const tf2_ros::Buffer& buffer, const std::string& target_frame,
                         const std::string& source_frame, const ros::Time& time,
                         const ros::Duration& timeout, Eigen::Isometry3d& target_from_source,
                         std::string* error = nullptr, ros::Time* stamp = nullptr);

/// The application layer's view of tf: every frame's pose in `fixed_frame` at `time` (zero =
/// latest), through lookupTransformSafe(), with the transform's stamp in seconds (0 = timeless).
/// The buffer must outlive the returned function.
app::TransformLookup tfLookup(const tf2_ros::Buffer& buffer, const std::string& fixed_frame,
                              const ros::Time& time, const ros::Duration& timeout);

}  // namespace ellipse_collision
