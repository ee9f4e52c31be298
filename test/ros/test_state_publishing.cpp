// rostest client (state_publishing.test): ~collisions keeps the rhythm of `rate` while a client
// calls ~check_collisions on an unchanged scene, and a full call whose answer changed the state
// publishes it. (With rate 0 every full call publishes: test_node_cli.)
#include <gtest/gtest.h>
#include <ros/ros.h>

#include "ellipse_collision/ros/messages.h"
#include "node_test_utils.h"

namespace ellipse_collision {
namespace {

using test::nodeTopic;

TEST(StatePublishing, FullCallsOnAnUnchangedSceneDoNotFloodTheTopicAndAChangeIsPublished) {
  ros::NodeHandle nh;
  test::Recorder<CollisionState> states(nh, nodeTopic("collisions"));
  ASSERT_TRUE(states.waitForLatest(
      [](const CollisionState& s) { return test::findPair(s.collisions, "arm", "crate"); }, 20.0));
  ros::ServiceClient check =
      nh.serviceClient<CheckCollisions>(nodeTopic("check_collisions"), /*persistent=*/true);
  ASSERT_TRUE(check.waitForExistence(ros::Duration(20.0)));

  // 100 full calls 10 ms apart on a scene that stands still: the 20 Hz periodic states only.
  // Publishing every call would add about 100 (back to back, the publisher's queue of one would
  // drop most of them, hence the pause).
  const std::size_t before = states.count();
  const ros::WallTime start = ros::WallTime::now();
  for (int call = 0; call < 100; ++call) {
    CheckCollisions srv;
    ASSERT_TRUE(check.call(srv) && srv.response.success) << srv.response.message;
    ASSERT_EQ(srv.response.collisions.size(), 1u);
    ros::WallDuration(0.01).sleep();
  }
  ros::WallDuration(0.2).sleep();  // the last states arrive
  const double elapsed_s = (ros::WallTime::now() - start).toSec();
  const std::size_t published = states.count() - before;
  EXPECT_LE(published, static_cast<std::size_t>(20.0 * elapsed_s) + 3)
      << published << " states in " << elapsed_s << " s";
  EXPECT_GE(published, static_cast<std::size_t>(10.0 * elapsed_s))
      << "the periodic check must keep publishing: " << published << " in " << elapsed_s << " s";

  // A change: the state of the call that saw it is published (and the topic carries it).
  AddObstacles add;
  Ellipse rock;
  rock.name = "rock";
  rock.frame_id = "map";
  rock.x = -0.4;
  rock.radius_x = 0.2;
  rock.radius_y = 0.2;
  add.request.obstacles.push_back(rock);
  ASSERT_TRUE(ros::service::call(nodeTopic("add_obstacles"), add) && add.response.success)
      << add.response.message;
  CheckCollisions srv;
  ASSERT_TRUE(check.call(srv) && srv.response.success);
  ASSERT_EQ(srv.response.collisions.size(), 2u);
  EXPECT_TRUE(states.waitForLatest(
      [](const CollisionState& s) { return test::findPair(s.collisions, "arm", "rock"); }, 5.0));
}

}  // namespace
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_state_publishing");
}
