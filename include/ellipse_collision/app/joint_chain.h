#pragma once

#include <Eigen/Core>
#include <vector>

namespace ellipse_collision::app {

/// One joint on the way from a robot model's root link to one of its links, as the URDF gives it:
/// the fixed rotation of its origin (parent link -> joint frame) and its motion.
struct ChainJoint {
  enum class Motion {
    Fixed,      ///< fixed
    Revolute,   ///< revolute or continuous: turns about `axis`
    Prismatic,  ///< slides along `axis`: no turn
    Free,       ///< floating, planar or anything else: may turn about any axis
  };
  Motion motion{Motion::Fixed};
  Eigen::Matrix3d origin_rotation{Eigen::Matrix3d::Identity()};  ///< parent -> joint frame
  Eigen::Vector3d axis{Eigen::Vector3d::UnitZ()};                 ///< in the joint frame
};

/// A joint axis or a link's z axis within this angle [rad] of the root's z axis counts as
/// parallel to it: URDF rotations come from roll-pitch-yaw in double (errors ~1e-16), so
/// anything beyond this is a real tilt.
constexpr double kUprightTolerance = 1e-9;

/// Whether the link at the end of `from_root` (its joints, root first) can tilt against the root:
/// its z axis leaves the root's z axis (up or down) at some joint value. Upright links (a mobile
/// base, a SCARA arm: every revolute joint on the way turns about a vertical axis, every fixed
/// origin keeps z vertical) stay planar ellipses in their own xy-plane; a link that can tilt
/// needs its ellipsoid (its planar ellipse would shrink to a sliver seen edge-on).
///
/// Why it suffices to look at the joint values 0: a turn about the vertical maps vertical axes to
/// vertical axes, so while every joint up the chain turns about a vertical axis (at 0), every
/// axis further down stays vertical at any joint value; the first one that is not vertical tilts
/// everything after it. The root itself is taken as upright (its tf parent, odom or map, is).
bool jointChainTilts(const std::vector<ChainJoint>& from_root);

}  // namespace ellipse_collision::app
