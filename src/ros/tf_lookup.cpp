#include "ellipse_collision/ros/tf_lookup.h"

#include <tf2/exceptions.h>
#include <tf2_eigen/tf2_eigen.h>

namespace ellipse_collision {

bool lookupTransformSafe(const tf2_ros::Buffer& buffer, const std::string& target_frame,
                         const std::string& source_frame, const ros::Time& time,
                         const ros::Duration& timeout, Eigen::Isometry3d& target_from_source,
                         std::string* error, ros::Time* stamp) {
  if (target_frame == source_frame) {
    target_from_source = Eigen::Isometry3d::Identity();
    if (stamp) *stamp = ros::Time(0);
    return true;
  }
  try {
    const geometry_msgs::TransformStamped found =
        buffer.lookupTransform(target_frame, source_frame, time, timeout);
    target_from_source = tf2::transformToEigen(found);
    if (stamp) *stamp = found.header.stamp;
    return true;
  } catch (const tf2::TransformException& exception) {
    // Not logged here: the caller reports it once, with what it costs (the skipped ellipses'
    // warning, the service's answer, /diagnostics).
    if (error) *error = exception.what();
    return false;
  }
}

app::TransformLookup tfLookup(const tf2_ros::Buffer& buffer, const std::string& fixed_frame,
                              const ros::Time& time, const ros::Duration& timeout) {
  return [&buffer, fixed_frame, time, timeout](const std::string& frame) {
    app::FrameTransform transform;
    ros::Time stamp;
    transform.ok = lookupTransformSafe(buffer, fixed_frame, frame, time, timeout,
                                       transform.fixed_from_frame, &transform.error, &stamp);
    // tf2 stamps a chain of static transforms 0 at the latest time: timeless, never stale.
    transform.stamp_s = stamp.toSec();
    return transform;
  };
}

}  // namespace ellipse_collision
