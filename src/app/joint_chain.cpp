#include "ellipse_collision/app/joint_chain.h"

#include <Eigen/Geometry>
#include <cmath>

namespace ellipse_collision::app {
namespace {

/// Whether `direction` (in the root's axes) is within kUprightTolerance of +-z; a zero or
/// non-finite one has no direction and is not.
bool vertical(const Eigen::Vector3d& direction) {
  const double length = direction.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  return (direction / length).cross(Eigen::Vector3d::UnitZ()).norm() <= kUprightTolerance;
}

}  // namespace

bool jointChainTilts(const std::vector<ChainJoint>& from_root) {
  Eigen::Matrix3d root_from_frame = Eigen::Matrix3d::Identity();  // at joint values 0
  for (const ChainJoint& joint : from_root) {
    root_from_frame = root_from_frame * joint.origin_rotation;
    switch (joint.motion) {
      case ChainJoint::Motion::Fixed:
      case ChainJoint::Motion::Prismatic:
        break;
      case ChainJoint::Motion::Revolute:
        if (!vertical(root_from_frame * joint.axis)) return true;
        break;
      case ChainJoint::Motion::Free:
        return true;
    }
  }
  return !vertical(root_from_frame.col(2));
}

}  // namespace ellipse_collision::app
