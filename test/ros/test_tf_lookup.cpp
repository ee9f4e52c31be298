// The node's one way to ask tf (ros/tf_lookup.h), on a tf2 buffer filled by the test: poses of
// chains against their composition by hand, the identity of a frame in itself, the stamps that
// make a transform timeless or dated, the tf error of a frame that is missing. No master.
#include <gtest/gtest.h>
#include <ros/time.h>
#include <tf2_ros/buffer.h>

#include <cmath>
#include <string>

#include "ellipse_collision/ros/tf_lookup.h"
#include "planar_transform.h"

namespace ellipse_collision {
namespace {

class TfLookup : public ::testing::Test {
 protected:
  void SetUp() override {
    ros::Time::init();                      // tf2_ros' waits read the clock; no node is needed
    buffer_.setUsingDedicatedThread(true);  // as the node's, whose listener fills it from a thread
    buffer_.setTransform(test::planarTransform("map", "odom", 1.0, 2.0, 0.5, ros::Time(0)), "test",
                         true);
    buffer_.setTransform(test::planarTransform("odom", "base_link", 3.0, 0.0, 0.25, ros::Time(100)),
                         "test");
    buffer_.setTransform(test::planarTransform("odom", "base_link", 4.0, 0.0, 0.25, ros::Time(102)),
                         "test");
  }
  tf2_ros::Buffer buffer_;
};

TEST_F(TfLookup, AChainIsTheCompositionOfItsTransforms) {
  Eigen::Isometry3d pose;
  std::string error;
  ros::Time stamp;
  ASSERT_TRUE(lookupTransformSafe(buffer_, "map", "base_link", ros::Time(101), ros::Duration(0),
                                  pose, &error, &stamp))
      << error;
  // map <- odom: (1, 2) turned 0.5; odom <- base_link at 101 s: (3.5, 0) turned 0.25 (linear
  // interpolation between the two stamps).
  const long double c = std::cos(0.5L), s = std::sin(0.5L);
  EXPECT_NEAR(pose.translation().x(), static_cast<double>(1.0L + c * 3.5L), 1e-12);
  EXPECT_NEAR(pose.translation().y(), static_cast<double>(2.0L + s * 3.5L), 1e-12);
  EXPECT_NEAR(std::atan2(pose.linear()(1, 0), pose.linear()(0, 0)), 0.75, 1e-12);
  EXPECT_EQ(stamp, ros::Time(101));
}

TEST_F(TfLookup, AFrameInItselfIsTheTimelessIdentityEvenUnknownToTf) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().x() = 9.0;
  ros::Time stamp(5);
  EXPECT_TRUE(lookupTransformSafe(buffer_, "nowhere", "nowhere", ros::Time(0), ros::Duration(0),
                                  pose, nullptr, &stamp));
  EXPECT_TRUE(pose.matrix().isIdentity(0.0));
  EXPECT_EQ(stamp, ros::Time(0));
}

TEST_F(TfLookup, AMissingFrameOrATimeOutsideTheBufferIsAnErrorNamingIt) {
  Eigen::Isometry3d pose;
  std::string error;
  EXPECT_FALSE(
      lookupTransformSafe(buffer_, "map", "gripper", ros::Time(0), ros::Duration(0), pose, &error));
  EXPECT_NE(error.find("gripper"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(lookupTransformSafe(buffer_, "map", "base_link", ros::Time(200), ros::Duration(0),
                                   pose, &error))
      << "extrapolation into the future";
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(lookupTransformSafe(buffer_, "map", "gripper", ros::Time(0), ros::Duration(0), pose))
      << "no error string asked for";
}

TEST_F(TfLookup, TheApplicationsViewCarriesStampsInSecondsAndStaticChainsAreTimeless) {
  const app::TransformLookup latest = tfLookup(buffer_, "map", ros::Time(0), ros::Duration(0));
  const app::FrameTransform base = latest("base_link");
  ASSERT_TRUE(base.ok) << base.error;
  EXPECT_EQ(base.stamp_s, 102.0) << "the latest common time of the chain";
  EXPECT_NEAR(base.fixed_from_frame.translation().x(), 1.0 + std::cos(0.5) * 4.0, 1e-12);
  const app::FrameTransform odom = latest("odom");
  ASSERT_TRUE(odom.ok);
  EXPECT_EQ(odom.stamp_s, 0.0) << "a static transform at the latest time never goes stale";
  const app::FrameTransform map = latest("map");
  EXPECT_TRUE(map.ok);
  EXPECT_EQ(map.stamp_s, 0.0);
  const app::FrameTransform missing = latest("gripper");
  EXPECT_FALSE(missing.ok);
  EXPECT_NE(missing.error.find("gripper"), std::string::npos) << missing.error;
  // At a given time.
  const app::FrameTransform at =
      tfLookup(buffer_, "map", ros::Time(100.5), ros::Duration(0))("base_link");
  ASSERT_TRUE(at.ok) << at.error;
  EXPECT_EQ(at.stamp_s, 100.5);
  EXPECT_NEAR(at.fixed_from_frame.translation().x(), 1.0 + std::cos(0.5) * 3.25, 1e-12);
}

}  // namespace
}  // namespace ellipse_collision
