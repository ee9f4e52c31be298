// Issue 14 through the real node (motion.test): ~check_path against the quad-precision
// first-contact oracle, a moving obstacle on a timed path, the time to contact of a link moved by
// tf, and every bad path request answered with the field and value while the node keeps serving.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

#include "ellipse_collision/ros/messages.h"
#include "first_contact_oracle.h"
#include "node_test_utils.h"

namespace ellipse_collision {
namespace {

using test::nodeTopic;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

geometry_msgs::PoseStamped pose(double x, double y, double yaw,
                                const ros::Time& stamp = ros::Time(0)) {
  geometry_msgs::PoseStamped p;
  p.header.stamp = stamp;
  p.pose.position.x = x;
  p.pose.position.y = y;
  p.pose.orientation.z = std::sin(0.5 * yaw);
  p.pose.orientation.w = std::cos(0.5 * yaw);
  return p;
}

core::Ellipse circle(double x, double y, double r) {
  core::Ellipse e;
  e.center = {x, y};
  e.radius_x = r;
  e.radius_y = r;
  return e;
}

core::Ellipse ellipse(double x, double y, double rx, double ry) {
  core::Ellipse e = circle(x, y, rx);
  e.radius_y = ry;
  return e;
}

class Motion : public ::testing::Test, public test::NodeServiceClient {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService(nodeTopic("check_path"), ros::Duration(30)));
    connectServices(nh_);
    path_ = nh_.serviceClient<CheckPath>(nodeTopic("check_path"));
    // The node does not wait for transforms (tf_timeout 0): first let tf_test_broadcaster's
    // static map -> base_link reach it.
    ASSERT_TRUE(test::waitUntil([this] { return checkPath({pose(0, 0, 0)}).success; }, 30.0));
  }

  CheckPath::Response checkPath(const std::vector<geometry_msgs::PoseStamped>& poses,
                                const std::string& frame = "map", const std::string& moving = "") {
    CheckPath srv;
    srv.request.path.header.frame_id = frame;
    srv.request.path.poses = poses;
    srv.request.moving_frame = moving;
    EXPECT_TRUE(path_.call(srv)) << "the node stopped serving ~check_path";
    return srv.response;
  }

  ros::NodeHandle nh_;
  ros::ServiceClient path_;
};

TEST_F(Motion, ThinWallBetweenTwoPosesIsFoundThoughEachPoseAloneIsClear) {
  const CheckPath::Response start = checkPath({pose(0, 0, 0)});
  const CheckPath::Response end = checkPath({pose(10, 0, 0)});
  ASSERT_TRUE(start.success) << start.message;
  ASSERT_TRUE(end.success) << end.message;
  EXPECT_TRUE(start.collision_free);
  EXPECT_TRUE(end.collision_free);

  const CheckPath::Response r = checkPath({pose(0, 0, 0), pose(10, 0, 0)});
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_FALSE(r.collision_free);
  EXPECT_EQ(r.segment, 0u);
  EXPECT_EQ(r.name_a, "arm");
  EXPECT_EQ(r.name_b, "wall");
  // The oracle: arm (0.2 x 0.05 at x = 0.5) moving 10 m along x against the standing wall.
  const core::test::OracleFirstContact oracle =
      core::test::oracleFirstContact(ellipse(0.5, 0, 0.2, 0.05), core::Motion{{10.0, 0.0}, 0.0},
                                     ellipse(5, 0, 0.01, 1.0), core::Motion{}, 1.0);
  ASSERT_TRUE(oracle.contact);
  std::printf("thin wall: fraction %.15g, oracle %.15g, error %.3g\n", r.fraction,
              static_cast<double>(oracle.time), r.fraction - static_cast<double>(oracle.time));
  EXPECT_NEAR(r.fraction, static_cast<double>(oracle.time), 1e-12);
  EXPECT_EQ(r.time, 0.0);  // a geometric path
  // Clearance at the first pose only (the second comes after the contact): arm to wall.
  EXPECT_EQ(r.min_clearance_pose, 0u);
  EXPECT_EQ(r.clearance_name_a, "arm");
  EXPECT_EQ(r.clearance_name_b, "wall");
  EXPECT_NEAR(r.min_clearance, 5.0 - 0.01 - 0.7, 1e-9);
}

TEST_F(Motion, TurningPathIsCheckedContinuously) {
  // Turning in place by 170 deg (shortest rotation) sweeps the arm through the crosser placed
  // behind and to the left; neither pose touches it.
  Ellipse crosser = test::ellipseMsg("turn_post", "map", -0.35, 0.35, 0.05, 0.05);
  ASSERT_TRUE(add({crosser}).success);
  const double yaw = 170.0 * M_PI / 180.0;
  const CheckPath::Response still = checkPath({pose(0, 0, 0)});
  const CheckPath::Response turned = checkPath({pose(0, 0, yaw)});
  EXPECT_TRUE(still.collision_free);
  EXPECT_TRUE(turned.collision_free);
  const CheckPath::Response r = checkPath({pose(0, 0, 0), pose(0, 0, yaw)});
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_FALSE(r.collision_free);
  EXPECT_EQ(r.name_b, "turn_post");
  // The other way round (-190 deg is not the shortest rotation: still +170 deg).
  const CheckPath::Response back = checkPath({pose(0, 0, yaw), pose(0, 0, 0)});
  EXPECT_FALSE(back.collision_free);
  ASSERT_TRUE(remove({"turn_post"}).success);
}

TEST_F(Motion, TimedPathMeetsAMovingObstacleAtTheOracleTime) {
  // An obstacle crossing the robot's way at 1 m/s along y; the robot drives at 1 m/s along x.
  Ellipse crosser = test::ellipseMsg("crosser", "map", 2.5, -3.0, 0.2, 0.2);
  crosser.vy = 1.0;
  ASSERT_TRUE(add({crosser}).success);
  // Stamps from a little ahead, so the obstacle's position at the first pose is well defined:
  // the node moves it from the time of the call to the first stamp.
  const ros::Time t0 = ros::Time::now() + ros::Duration(1.0);
  std::vector<geometry_msgs::PoseStamped> poses;
  for (int i = 0; i <= 4; ++i) poses.push_back(pose(i, 0, 0, t0 + ros::Duration(i)));
  const ros::Time before = ros::Time::now();
  const CheckPath::Response r = checkPath(poses);
  const ros::Time after = ros::Time::now();
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_FALSE(r.collision_free);
  EXPECT_EQ(r.name_b, "crosser");
  // Oracle: the obstacle at the first pose's time is 1 m/s x (t0 - call time) further along y;
  // the call time lies in [before, after].
  const auto oracleTime = [&](const ros::Time& call) {
    const double lead = (t0 - call).toSec();
    double best = 1e9;
    for (const core::Ellipse& link : {circle(0, 0, 0.3), ellipse(0.5, 0, 0.2, 0.05)}) {
      const auto c = core::test::oracleFirstContact(link, core::Motion{{1.0, 0.0}, 0.0},
                                                    circle(2.5, -3.0 + lead, 0.2),
                                                    core::Motion{{0.0, 1.0}, 0.0}, 4.0);
      if (c.contact) best = std::min(best, static_cast<double>(c.time));
    }
    return best;
  };
  const double early = oracleTime(after), late = oracleTime(before);
  std::printf("timed path: time %.9g s, oracle within [%.9g, %.9g] (call latency %.3g s)\n", r.time,
              std::min(early, late), std::max(early, late), (after - before).toSec());
  EXPECT_GE(r.time, std::min(early, late) - 1e-9);
  EXPECT_LE(r.time, std::max(early, late) + 1e-9);
  EXPECT_EQ(r.segment, static_cast<std::uint32_t>(std::floor(r.time)));
  EXPECT_NEAR(r.segment + r.fraction, r.time, 1e-9);
  // The same poses without stamps: a geometric path, the crosser stands still at y = -3.
  for (auto& p : poses) p.header.stamp = ros::Time(0);
  const CheckPath::Response still = checkPath(poses);
  ASSERT_TRUE(still.success) << still.message;
  EXPECT_TRUE(still.collision_free) << still.name_a << " / " << still.name_b;
  ASSERT_TRUE(remove({"crosser"}).success);
}

TEST_F(Motion, TimeToContactOfALinkMovedByTfMatchesTheAnalyticTime) {
  // The client moves `mover` along y = -10 at 0.5 m/s from x = -2.5: the probe (0.1 m) meets
  // block (0.2 m at x = 0) when the probe's x reaches -0.3, 4.4 s after the start.
  constexpr double kSpeed = 0.5, kStartX = -2.5, kContactX = -0.3;
  tf2_ros::TransformBroadcaster broadcaster;
  const ros::Time start = ros::Time::now();
  std::atomic<bool> stop{false};
  std::thread mover([&] {
    ros::Rate rate(50.0);
    while (!stop && ros::ok()) {
      geometry_msgs::TransformStamped t;
      t.header.frame_id = "map";
      t.child_frame_id = "mover";
      t.header.stamp = ros::Time::now();
      t.transform.translation.x = kStartX + kSpeed * (t.header.stamp - start).toSec();
      t.transform.translation.y = -10.0;
      t.transform.rotation.w = 1.0;
      broadcaster.sendTransform(t);
      rate.sleep();
    }
  });
  test::Recorder<CollisionState> states(nh_, nodeTopic("collisions"));
  test::Recorder<diagnostic_msgs::DiagnosticArray> diagnostics(nh_, "/diagnostics");
  const auto predicted = [](const CollisionState& s) {
    for (const PredictedContact& p : s.predicted) {
      if (p.name_a == "probe" && p.name_b == "block") return true;
    }
    return false;
  };
  // Let the finite difference see a full window of motion first.
  ros::Duration(0.5).sleep();
  CollisionState state;
  ASSERT_TRUE(states.waitForLatest(predicted, 10.0, &state));
  // Several checks; each predicted time against the analytic one at the check's stamp.
  double worst = 0.0;
  int compared = 0;
  ros::Duration(1.0).sleep();
  for (const CollisionState& s : states.all()) {
    if (!predicted(s) || (s.header.stamp - start).toSec() < 0.5) continue;
    const PredictedContact& p = s.predicted.front();
    ASSERT_EQ(p.name_a, "probe");
    const double x_at_stamp = kStartX + kSpeed * (s.header.stamp - start).toSec();
    const double analytic = (kContactX - x_at_stamp) / kSpeed;
    worst = std::max(worst, std::fabs(p.time - analytic));
    ++compared;
  }
  // ~check_collisions answers the same, for the pairs it is asked about, soonest first.
  const CheckCollisions::Response asked = check({"probe"});
  ASSERT_TRUE(asked.success) << asked.message;
  ASSERT_FALSE(asked.predicted.empty());
  EXPECT_EQ(asked.predicted.front().name_a, "probe");
  EXPECT_EQ(asked.predicted.front().name_b, "block");
  EXPECT_GT(asked.predicted.front().time, 0.0);
  EXPECT_LT(asked.predicted.front().time, 4.4);
  EXPECT_TRUE(check({"wall"}).predicted.empty()) << "a filter on a pair that will not touch";
  stop = true;
  mover.join();
  std::printf("time to contact: %d checks compared, largest |predicted - analytic| = %.4g s\n",
              compared, worst);
  EXPECT_GT(compared, 5);
  // The node moves each pose on from its transform's stamp to the check's stamp, so what is left
  // is the finite difference and tf's interpolation of a straight, uniform motion: 1 ms.
  EXPECT_LT(worst, 0.001);
  // /diagnostics names the smallest time to contact.
  bool named = false;
  for (const auto& array : diagnostics.all()) {
    for (const auto& status : array.status) {
      for (const auto& kv : status.values) {
        if (kv.key == "smallest time to contact [s]" && kv.value != "none") named = true;
      }
    }
  }
  EXPECT_TRUE(named);
}

TEST_F(Motion, EachBadPathIsAnsweredWithFieldAndValueAndTheNodeKeepsServing) {
  struct Bad {
    const char* what;
    std::vector<geometry_msgs::PoseStamped> poses;
    std::string frame, moving;
    std::vector<std::string> expected;  // substrings of the message
  };
  geometry_msgs::PoseStamped nan_pose = pose(kNaN, 0, 0);
  geometry_msgs::PoseStamped long_q = pose(1, 0, 0);
  long_q.pose.orientation.w = 2.0;
  geometry_msgs::PoseStamped tilted = pose(1, 0, 0);
  tilted.pose.orientation.x = std::sin(0.25);
  tilted.pose.orientation.w = std::cos(0.25);
  const ros::Time t = ros::Time::now();
  const std::vector<Bad> cases = {
      {"empty path", {}, "map", "", {"path.poses", "empty"}},
      {"non-finite pose",
       {pose(0, 0, 0), nan_pose},
       "map",
       "",
       {"path.poses[1].pose.position.x = nan"}},
      {"quaternion far from unit",
       {long_q},
       "map",
       "",
       {"path.poses[0].pose.orientation", "|q| = 2"}},
      {"rotation out of the plane",
       {pose(0, 0, 0), tilted},
       "map",
       "",
       {"path.poses[1].pose.orientation", "rotation about z only"}},
      {"unknown moving frame",
       {pose(0, 0, 0)},
       "map",
       "no_such_frame",
       {"moving_frame = 'no_such_frame'"}},
      {"unknown path frame", {pose(0, 0, 0)}, "nowhere", "", {"path.header.frame_id = 'nowhere'"}},
      {"decreasing stamps",
       {pose(0, 0, 0, t + ros::Duration(2)), pose(1, 0, 0, t + ros::Duration(1))},
       "map",
       "",
       {"path.poses[1].header.stamp", "strictly increasing"}},
  };
  for (const Bad& bad : cases) {
    const CheckPath::Response r = checkPath(bad.poses, bad.frame, bad.moving);
    EXPECT_FALSE(r.success) << bad.what;
    for (const std::string& part : bad.expected) {
      EXPECT_NE(r.message.find(part), std::string::npos) << bad.what << ": " << r.message;
    }
    const CheckPath::Response good = checkPath({pose(0, 0, 0), pose(1, 0, 0)});
    EXPECT_TRUE(good.success) << "after " << bad.what << ": " << good.message;
  }
  // 10^6 poses: refused above the documented limit of 100,000.
  const std::vector<geometry_msgs::PoseStamped> huge(1000000, pose(0, 0, 0));
  const CheckPath::Response r = checkPath(huge);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("at most 100000 poses, got 1000000"), std::string::npos) << r.message;
  EXPECT_TRUE(checkPath({pose(0, 0, 0)}).success);
}

}  // namespace
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_motion");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  ros::shutdown();
  return result;
}
