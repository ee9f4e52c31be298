// rostest client: runtime obstacles survive a crash (issue 12). The node is killed with SIGKILL
// right after ~add_obstacles answers; roslaunch respawns it and it comes back with every obstacle it
// had acknowledged (service calls) and the topic obstacles written within obstacle_store_period of
// their message, topic obstacles still subject to obstacle_timeout (5 s here), and without the ones
// it had removed, also a topic obstacle removed through the service.
#include <signal.h>

#include <chrono>
#include <cmath>

#include "../reliability/reliability_utils.h"
#include "node_test_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

class Respawn : public ::testing::Test, protected NodeServiceClient {
 protected:
  void SetUp() override {
    ASSERT_TRUE(connectServicesAndObstacles(nh_, obstacles_, 10));
  }

  /// SIGKILL, then wait for the respawned node to serve again; returns the seconds it took.
  double killAndWaitForRespawn() {
    const int pid = nodePid("/ellipse_collision");
    EXPECT_GT(pid, 0);
    const auto killed = std::chrono::steady_clock::now();
    EXPECT_EQ(::kill(pid, SIGKILL), 0);
    EXPECT_TRUE(waitUntil(
        [&] {
          const int now = nodePid("/ellipse_collision");
          return now > 0 && now != pid;
        },
        30.0));
    EXPECT_TRUE(ros::service::waitForService(nodeTopic("check_collisions"), ros::Duration(30)));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - killed).count();
    connectServices(nh_);
    return seconds;
  }

  ros::NodeHandle nh_;
  ros::Publisher obstacles_;
};

TEST_F(Respawn, KilledNodeComesBackWithEveryAcknowledgedObstacle) {
  // Service obstacles: one on the body, one replaced, one removed again.
  ASSERT_TRUE(add({ellipseMsg("box", "base_link", 0.0, 0.0, 0.1, 0.1),
                   ellipseMsg("temp", "base_link", 20.0, 0.0, 0.1, 0.1)})
                  .success);
  ASSERT_TRUE(add({ellipseMsg("spare", "base_link", 0.0, 0.2, 0.1, 0.1)}).success);
  ASSERT_TRUE(remove({"temp"}).success);
  // Ellipsoids standing on their side (rolled a quarter turn), a service and a topic one: only
  // their shadows reach body (y <= 0.3) and arm (y <= 0.1), their planar ellipses would not.
  ASSERT_TRUE(
      add({ellipsoidMsg("slab", "base_link", -0.2, 0.7, 0.1, 0.02, 0.5, M_PI / 2)}).success);
  // Topic obstacles, stamped now.
  ASSERT_TRUE(waitUntil(
      [&] {
        publishObstacles(obstacles_, "base_link",
                         {ellipseMsg("rock", "", 1.0, 0.3, 0.1, 0.3),
                          ellipsoidMsg("cluster", "", 1.0, 0.6, 0.1, 0.02, 0.55, M_PI / 2)});
        return isStored("rock");
      },
      10.0));
  EXPECT_TRUE(findPair(check().collisions, "arm", "cluster"));
  EXPECT_TRUE(findPair(check().collisions, "body", "slab"));
  // Topic obstacles reach the store within obstacle_store_period (1 s) of their message; a
  // service call writes only the service record beside it, so that it does not rewrite a
  // perception stream's obstacles. After the period the store holds the rock.
  ros::WallDuration(1.5).sleep();
  // The very last acknowledged change, immediately before the kill: only in the service record,
  // which the respawned node folds into the store.
  ASSERT_TRUE(add({ellipseMsg("last", "base_link", -0.4, 0.0, 0.1, 0.1)}).success);

  const double respawn_s = killAndWaitForRespawn();
  std::printf("respawned and serving after %.3f s\n", respawn_s);

  const CheckCollisions::Response r = check();
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_TRUE(findPair(r.collisions, "body", "box"));
  EXPECT_TRUE(findPair(r.collisions, "body", "spare")) << "the replaced configured obstacle";
  EXPECT_TRUE(findPair(r.collisions, "body", "last"));
  EXPECT_TRUE(findPair(r.collisions, "arm", "rock"));
  EXPECT_TRUE(findPair(r.collisions, "body", "slab")) << "the service ellipsoid, by its shadow";
  EXPECT_TRUE(findPair(r.collisions, "arm", "cluster")) << "the topic ellipsoid, by its shadow";
  EXPECT_FALSE(isStored("temp")) << "removed before the kill";
  EXPECT_TRUE(isStored("rock"));

  // The topic obstacle keeps its stamp: dropped 5 s after its message, as before the crash.
  EXPECT_TRUE(waitUntil([&] { return !isStored("rock"); }, 7.0));
  EXPECT_TRUE(isStored("box"));

  // Removed obstacles stay removed across another crash, a topic obstacle too (that call writes
  // the whole store, not only the service record).
  ASSERT_TRUE(waitUntil(
      [&] {
        publishObstacles(obstacles_, "base_link", {ellipseMsg("stone", "", 1.0, 0.3, 0.1, 0.3)});
        return isStored("stone");
      },
      10.0));
  ros::WallDuration(1.5).sleep();  // the stone in the store
  ASSERT_TRUE(remove({"box", "last", "stone"}).success);
  killAndWaitForRespawn();
  EXPECT_FALSE(isStored("box"));
  EXPECT_FALSE(isStored("last"));
  EXPECT_FALSE(isStored("stone")) << "a topic obstacle removed through the service";
  EXPECT_TRUE(isStored("spare"));
  EXPECT_TRUE(findPair(check().collisions, "body", "spare")) << "still the service's replacement";
}

TEST_F(Respawn, TopicObstaclesReachTheStoreWithinObstacleStorePeriod) {
  // No service call after the message this time: only the store's background write (at most
  // obstacle_store_period, 1 s by default, after the message) can bring the obstacle back.
  ASSERT_TRUE(waitUntil(
      [&] {
        publishObstacles(obstacles_, "base_link", {ellipseMsg("boulder", "", 1.0, 0.3, 0.1, 0.3)});
        return isStored("boulder");
      },
      10.0));
  ros::WallDuration(1.5).sleep();
  killAndWaitForRespawn();
  EXPECT_TRUE(isStored("boulder")) << "written within the period, restored after the crash";
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_respawn");
}
