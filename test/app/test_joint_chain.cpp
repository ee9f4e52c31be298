// app::jointChainTilts() against forward kinematics: random chains of fixed, revolute, prismatic
// and free joints, with vertical and tilted axes and origins, judged by the rule and by sampling
// joint values (a link tilts when its z axis leaves the vertical at some sampled configuration).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "ellipse_collision/app/joint_chain.h"

namespace ellipse_collision::app {
namespace {

using Motion = ChainJoint::Motion;
constexpr double kPi = 3.14159265358979323846;

ChainJoint joint(Motion motion, const Eigen::Vector3d& axis,
                 const Eigen::Matrix3d& origin = Eigen::Matrix3d::Identity()) {
  ChainJoint j;
  j.motion = motion;
  j.axis = axis;
  j.origin_rotation = origin;
  return j;
}

Eigen::Matrix3d rpy(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

/// The oracle: the link's z axis at `samples` random joint values (a free joint turns about a
/// random axis), tilted if any leaves the vertical by more than 1e-6.
bool tiltsAtSomeSample(const std::vector<ChainJoint>& chain, std::mt19937& rng, int samples = 64) {
  std::uniform_real_distribution<double> angle(-kPi, kPi), unit(-1.0, 1.0);
  for (int s = 0; s < samples; ++s) {
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    for (const ChainJoint& j : chain) {
      r = r * j.origin_rotation;
      if (j.motion == Motion::Revolute) {
        r = r * Eigen::AngleAxisd(angle(rng), j.axis.normalized()).toRotationMatrix();
      } else if (j.motion == Motion::Free) {
        const Eigen::Vector3d axis(unit(rng), unit(rng), unit(rng));
        r = r * Eigen::AngleAxisd(angle(rng), axis.normalized()).toRotationMatrix();
      }
    }
    if (r.col(2).cross(Eigen::Vector3d::UnitZ()).norm() > 1e-6) return true;
  }
  return false;
}

TEST(JointChain, NamedCases) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  EXPECT_FALSE(jointChainTilts({}));  // the root
  // A mobile base and a SCARA arm: every revolute joint about a vertical axis.
  EXPECT_FALSE(jointChainTilts({joint(Motion::Fixed, x), joint(Motion::Revolute, z),
                                joint(Motion::Revolute, -z), joint(Motion::Prismatic, z)}));
  // Yawed mounts keep the vertical; a sensor mounted upside down too (its shadow is the same).
  EXPECT_FALSE(jointChainTilts({joint(Motion::Fixed, x, rpy(0, 0, 1.2))}));
  EXPECT_FALSE(jointChainTilts({joint(Motion::Fixed, x, rpy(kPi, 0, 0))}));
  // An arm's shoulder pitch, and everything after it, even a vertical elbow.
  EXPECT_TRUE(jointChainTilts({joint(Motion::Revolute, y)}));
  EXPECT_TRUE(jointChainTilts({joint(Motion::Revolute, y), joint(Motion::Revolute, z)}));
  // A frame mounted rolled by 90 degrees: fixed, but seen edge-on from above.
  EXPECT_TRUE(jointChainTilts({joint(Motion::Fixed, x, rpy(kPi / 2, 0, 0))}));
  // A revolute joint whose origin turns its axis from z to horizontal; a rolled frame turning
  // about its own y (the vertical) whose child is rolled back upright.
  EXPECT_TRUE(jointChainTilts({joint(Motion::Revolute, z, rpy(kPi / 2, 0, 0))}));
  EXPECT_FALSE(jointChainTilts({joint(Motion::Fixed, x, rpy(kPi / 2, 0, 0)),
                                joint(Motion::Revolute, y),
                                joint(Motion::Fixed, x, rpy(-kPi / 2, 0, 0))}));
  EXPECT_TRUE(jointChainTilts({joint(Motion::Fixed, x, rpy(kPi / 2, 0, 0)),
                               joint(Motion::Revolute, y)}));  // its own z is horizontal
  // Floating and planar joints may turn any way; a prismatic joint along x never turns.
  EXPECT_TRUE(jointChainTilts({joint(Motion::Free, z)}));
  EXPECT_FALSE(jointChainTilts({joint(Motion::Prismatic, x)}));
  // A tilt below the tolerance is rounding of roll-pitch-yaw; above it, a real tilt.
  EXPECT_FALSE(jointChainTilts({joint(Motion::Fixed, x, rpy(1e-12, 0, 0))}));
  EXPECT_TRUE(jointChainTilts({joint(Motion::Fixed, x, rpy(1e-6, 0, 0))}));
  // A zero axis (no direction) is not known to be vertical.
  EXPECT_TRUE(jointChainTilts({joint(Motion::Revolute, Eigen::Vector3d::Zero())}));
}

TEST(JointChain, AgreesWithForwardKinematicsOnRandomChains) {
  std::mt19937 rng(34);
  std::uniform_int_distribution<int> pick(0, 5), length(1, 6);
  const std::vector<Eigen::Matrix3d> origins = {
      Eigen::Matrix3d::Identity(), rpy(0, 0, 0.7), rpy(kPi, 0, 0), rpy(0, kPi, 0.3),
      rpy(kPi / 2, 0, 0), rpy(0, 0.4, 0)};
  const std::vector<Eigen::Vector3d> axes = {
      Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
      Eigen::Vector3d::UnitY(), Eigen::Vector3d(0.0, 0.6, 0.8), Eigen::Vector3d(0.0, 0.0, 2.0)};
  int tilted = 0, upright = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<ChainJoint> chain;
    for (int k = length(rng); k > 0; --k) {
      // Mostly vertical axes and upright origins, so that both answers are common.
      const int kind = pick(rng);
      const Motion motion = kind < 3 ? Motion::Revolute
                            : kind < 4 ? Motion::Fixed
                            : kind < 5 ? Motion::Prismatic
                                       : (pick(rng) == 0 ? Motion::Free : Motion::Fixed);
      const int a = pick(rng) < 4 ? pick(rng) % 2 : pick(rng);
      const int o = pick(rng) < 4 ? pick(rng) % 4 : pick(rng);
      chain.push_back(joint(motion, axes[a], origins[o]));
    }
    const bool expected = tiltsAtSomeSample(chain, rng);
    ASSERT_EQ(jointChainTilts(chain), expected) << "trial " << trial;
    ++(expected ? tilted : upright);
  }
  // Both answers were exercised.
  EXPECT_GT(tilted, 300);
  EXPECT_GT(upright, 300);
}

}  // namespace
}  // namespace ellipse_collision::app
