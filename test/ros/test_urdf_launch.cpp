// rostest client for urdf_launch.test: launch/ellipse_collision.launch started with
// links_from_urdf. The node answers ~check_collisions for each URDF link it was asked to fit
// (and refuses a name it was not), and the --check-config guard is still running: had it failed
// to read the URDF it would have exited, and being required, taken the launch down.
#include <ros/master.h>

#include <algorithm>
#include <string>
#include <vector>

#include "node_test_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

// The links urdf_launch.yaml selects from test/fixtures/every_geometry.urdf.
const std::vector<std::string> kUrdfLinks = {"box_link", "cylinder_link", "sphere_link",
                                             "mesh_link"};

bool nodeRunning(const std::string& name) {
  std::vector<std::string> nodes;
  return ros::master::getNodes(nodes) && std::count(nodes.begin(), nodes.end(), name) > 0;
}

TEST(PackageLaunchWithUrdf, NodeServesTheUrdfLinksAndTheGuardStays) {
  ros::NodeHandle nh;
  ros::ServiceClient check = nh.serviceClient<CheckCollisions>(nodeTopic("check_collisions"));
  ASSERT_TRUE(check.waitForExistence(ros::Duration(30.0))) << "the node never served";

  for (const std::string& link : kUrdfLinks) {
    CheckCollisions call;
    call.request.names = {link};
    ASSERT_TRUE(check.call(call)) << link;
    EXPECT_TRUE(call.response.success) << link << ": " << call.response.message;
    // Nothing publishes the URDF's frames here: each link is stored and waits for its frame.
    EXPECT_EQ(std::count(call.response.unavailable_frames.begin(),
                         call.response.unavailable_frames.end(), link),
              1)
        << link << " is not among the stored links waiting for their frames";
  }
  CheckCollisions unknown;
  unknown.request.names = {"lying_cylinder_link"};  // in the URDF, not selected
  ASSERT_TRUE(check.call(unknown));
  EXPECT_FALSE(unknown.response.success) << "a link the configuration did not select is stored";

  // The guard fits the same URDF; it idles unless the configuration is bad. Give a failing
  // guard time to exit (it would end the launch and this test with it).
  ros::WallDuration(3.0).sleep();
  EXPECT_TRUE(nodeRunning("/ellipse_collision_config_check")) << "the config guard is gone";
  EXPECT_TRUE(nodeRunning("/ellipse_collision")) << "the node is gone";
  CheckCollisions again;
  ASSERT_TRUE(check.call(again));
  EXPECT_TRUE(again.response.success) << again.response.message;
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_urdf_launch");
}
