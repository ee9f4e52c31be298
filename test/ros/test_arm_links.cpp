// rostest client for arm_links.test: the links of test/fixtures/two_link_arm.urdf fitted as
// ellipsoids. The shoulder rolls and pitches through 0..180 degrees (13 x 13 poses, published on
// tf); at each pose ~check_collisions must (a) place the upper arm's footprint over its whole
// projected cylinder: probes of radius 1 um at projected rim points of both end discs (the
// shadow of a cylinder is the hull of its projected end discs) all collide with upper_arm, and
// (b) report the post at the shoulder, which the arm's shadow covers at every angle.
#include <geometry_msgs/TransformStamped.h>
#include <tf2_ros/transform_broadcaster.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "node_test_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRimProbes = 24;  // per end disc

geometry_msgs::TransformStamped transform(const std::string& parent, const std::string& child,
                                          const Eigen::Vector3d& at, const Eigen::Quaterniond& q,
                                          const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = at.x();
  t.transform.translation.y = at.y();
  t.transform.translation.z = at.z();
  t.transform.rotation.w = q.w();
  t.transform.rotation.x = q.x();
  t.transform.rotation.y = q.y();
  t.transform.rotation.z = q.z();
  return t;
}

bool collide(const std::vector<CollisionPair>& pairs, const std::string& a, const std::string& b) {
  return findPair(pairs, a, b) || findPair(pairs, b, a);
}

TEST(ArmLinks, FootprintHoldsTheRollingAndPitchingArm) {
  ros::NodeHandle nh;
  ros::ServiceClient check = nh.serviceClient<CheckCollisions>(nodeTopic("check_collisions"));
  ASSERT_TRUE(check.waitForExistence(ros::Duration(30.0))) << "the node never served";
  tf2_ros::TransformBroadcaster tf;
  int poses = 0;
  for (int roll_step = 0; roll_step <= 12; ++roll_step) {
    for (int pitch_step = 0; pitch_step <= 12; ++pitch_step) {
      const double roll = roll_step * kPi / 12, pitch = pitch_step * kPi / 12;
      const Eigen::Quaterniond shoulder = Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                                          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
      const ros::Time stamp = ros::Time::now();
      const auto publish = [&] {
        tf.sendTransform(
            transform("base_link", "upper_arm", Eigen::Vector3d::Zero(), shoulder, stamp));
        tf.sendTransform(transform("upper_arm", "forearm", Eigen::Vector3d(0.4, 0, 0),
                                   Eigen::Quaterniond::Identity(), stamp));
      };
      CheckCollisions srv;
      srv.request.stamp = stamp;
      for (const double end : {0.0, 0.4}) {
        for (int k = 0; k < kRimProbes; ++k) {
          const double t = 2 * kPi * k / kRimProbes;
          // The cylinder's axis is the link's x; its rim circles lie in the link's yz-plane.
          const Eigen::Vector3d p = shoulder * Eigen::Vector3d(end, 0.06 * std::cos(t), 0.06 * std::sin(t));
          srv.request.query.push_back(ellipseMsg("rim_" + std::to_string(srv.request.query.size()),
                                                 "base_link", p.x(), p.y(), 1e-6, 1e-6));
        }
      }
      // The node answers with the frame unavailable until the transform has reached its buffer
      // (the first ones go out before tf's subscriber is connected): publish again until then.
      ASSERT_TRUE(waitUntil(
          [&] {
            publish();
            return check.call(srv) && srv.response.success && srv.response.complete;
          },
          10.0))
          << "roll " << roll << " pitch " << pitch << ": " << srv.response.message;
      for (const Ellipse& probe : srv.request.query) {
        EXPECT_TRUE(collide(srv.response.collisions, probe.name, "upper_arm"))
            << "roll " << roll << " pitch " << pitch << ": projected rim point " << probe.name
            << " (" << probe.x << ", " << probe.y << ") outside the upper arm's footprint";
      }
      EXPECT_TRUE(collide(srv.response.collisions, "upper_arm", "post"))
          << "roll " << roll << " pitch " << pitch << ": the post at the shoulder is missed";
      ++poses;
    }
  }
  EXPECT_EQ(poses, 169);
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_arm_links");
}
