// A person crossing in front of a robot driven through the real node's velocity gate (issue 42,
// part 4): this client simulates the world on simulated time. Two collision nodes run side by
// side (crossings.test), one tracking its scan source, one not; each guards a robot of its own on a
// core::SimulatedBase (0.1 s late, braking at 1 m/s^2) that follows the node's ~cmd_vel_out, and
// sees its world only through a ray-cast 720-beam LaserScan at 40 Hz (synthetic_scan.h) with its
// base's tf and /odom. Commands of 1 m/s straight on go to ~cmd_vel_in at 20 Hz. Per crossing:
// contact while the base still moves, the closest approach, the gate's actions. Lockstep: each
// command waits for the node's answer before the clock moves on, so a slow machine slows the run,
// not the robot. Also: a cart that starts rolling toward a standing robot is reported moving.
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/transform_broadcaster.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "ellipse_collision/core/simulated_base.h"
#include "node_test_utils.h"
#include "planar_transform.h"
#include "synthetic_scan.h"

namespace ellipse_collision {
namespace {

constexpr double kScanPeriod = 0.025;   // [s] 40 Hz; a command every second scan (20 Hz)
constexpr double kContactStep = 0.005;  // [s] contact is checked this often along the motion
constexpr double kRobotRadius = 0.3;    // crossings_scene.yaml's `body`
constexpr double kPersonRadius = 0.25;  // the person
constexpr double kCruise = 1.0;         // [m/s] the planner's command, straight ahead
const core::BaseDynamics kBase{0.1, 1.0, 2.0};  // crossings_scene.yaml's gate/ limits

/// A round thing in the world [m], in odom; absent while `present` is false.
struct Mover {
  bool present{false};
  Eigen::Vector2d centre{0.0, 0.0};
  double radius{kPersonRadius};
};

/// What one robot and its node went through during a stretch of the run.
struct Outcome {
  bool contact_while_moving{false};
  double closest{1e9};  ///< [m] least gap between the robot's disc and the mover's
  std::map<std::string, int> actions;

  std::string actionList() const {
    std::ostringstream out;
    for (const auto& [action, count] : actions) out << action << " " << count << " ";
    return out.str();
  }
};

/// One robot, its node and its world: the base follows the node's ~cmd_vel_out.
class Robot {
 public:
  /// At rest at odom's origin at `t` [s] of the run.
  Robot(ros::NodeHandle& nh, const std::string& node, const std::string& prefix, double t)
      : node_(node),
        odom_frame_(prefix + "_odom"),
        base_frame_(prefix + "_base_link"),
        base_(kBase, core::PathPose{0.0, 0.0, 0.0, t}) {
    scan_pub_ = nh.advertise<sensor_msgs::LaserScan>("/" + prefix + "/scan", 10);
    odom_pub_ = nh.advertise<nav_msgs::Odometry>("/" + prefix + "/odom", 10);
    cmd_pub_ = nh.advertise<geometry_msgs::Twist>(node + "/cmd_vel_in", 10);
    state_sub_ = nh.subscribe(node + "/gate_state", 100, &Robot::onState, this);
    // Persistent: many calls to a node that never restarts (NodeServiceClient::connectServices()).
    check_ = nh.serviceClient<CheckCollisions>(node + "/check_collisions", /*persistent=*/true);
  }

  bool connected() {
    return scan_pub_.getNumSubscribers() > 0 && odom_pub_.getNumSubscribers() > 0 &&
           cmd_pub_.getNumSubscribers() > 0 && state_sub_.getNumPublishers() > 0 && check_.exists();
  }

  /// The base moves on to `t` [s] of the run; contact with `moverAt(time)` is judged every
  /// kContactStep.
  void advanceTo(double t, const std::function<Mover(double)>& moverAt) {
    while (base_.now() < t - 1e-9) {
      base_.advanceTo(std::min(t, base_.now() + kContactStep));
      const Mover mover = moverAt(base_.now());
      if (!mover.present) continue;
      const double gap = (mover.centre - position()).norm() - kRobotRadius - mover.radius;
      outcome_.closest = std::min(outcome_.closest, gap);
      if (gap < 0.0 && base_.moving()) outcome_.contact_while_moving = true;
    }
  }

  /// The base's tf and odometry at `stamp`, and the scan of the world it sees from there.
  void publishSensors(const ros::Time& stamp, const test::World& world, std::uint64_t seed) {
    const core::PathPose& pose = base_.pose();
    const geometry_msgs::TransformStamped t =
        test::planarTransform(odom_frame_, base_frame_, pose.x, pose.y, pose.yaw, stamp);
    tf_.sendTransform(t);

    nav_msgs::Odometry odom;
    odom.header = t.header;
    odom.child_frame_id = base_frame_;
    odom.twist.twist.linear.x = base_.velocity().vx;
    odom.twist.twist.linear.y = base_.velocity().vy;
    odom.twist.twist.angular.z = base_.velocity().wz;
    odom_pub_.publish(odom);

    // The world in the laser's frame (base_link): the laser at the base's centre.
    const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
    const auto local = [&](const Eigen::Vector2d& p) {
      const Eigen::Vector2d d = p - position();
      return Eigen::Vector2d(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
    };
    test::World seen;
    for (const test::WorldSegment& w : world.walls) seen.walls.push_back({local(w.a), local(w.b)});
    for (const test::WorldCircle& p : world.pillars)
      seen.pillars.push_back({local(p.centre), p.radius});
    const test::ScanFields fields = test::castScan(seen, 720, 10.0, 0.01, seed);
    sensor_msgs::LaserScan scan;
    scan.header.stamp = stamp;
    scan.header.frame_id = base_frame_;
    scan.angle_min = static_cast<float>(fields.angle_min);
    scan.angle_increment = static_cast<float>(fields.angle_increment);
    scan.angle_max =
        static_cast<float>(fields.angle_min + (fields.ranges.size() - 1) * fields.angle_increment);
    scan.range_min = static_cast<float>(fields.range_min);
    scan.range_max = static_cast<float>(fields.range_max);
    scan.scan_time = static_cast<float>(kScanPeriod);
    scan.ranges = fields.ranges;
    scan_pub_.publish(scan);
  }

  /// Sends `vx` [m/s] to ~cmd_vel_in; waitForAnswer() then applies the node's output at `t`.
  std::size_t sendCommand(double vx) {
    const std::size_t before = stateCount();
    geometry_msgs::Twist cmd;
    cmd.linear.x = vx;
    cmd_pub_.publish(cmd);
    return before;
  }
  bool waitForAnswer(std::size_t before, double t) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!answered_.wait_for(lock, std::chrono::seconds(10),
                            [&] { return states_.size() > before; }))
      return false;
    const GateState state = states_.back();
    lock.unlock();
    ++outcome_.actions[state.action];
    base_.command(t, {state.output.linear.x, state.output.linear.y, state.output.angular.z});
    return true;
  }

  /// The node's predicted contacts now (~check_collisions); a failed call fails the test.
  std::optional<std::vector<PredictedContact>> predicted() {
    CheckCollisions srv;
    const bool called = check_.call(srv);
    EXPECT_TRUE(called && srv.response.success)
        << node_ << ": ~check_collisions " << (called ? srv.response.message : "call failed");
    if (!called || !srv.response.success) return std::nullopt;
    return srv.response.predicted;
  }

  Eigen::Vector2d position() const { return {base_.pose().x, base_.pose().y}; }
  const core::SimulatedBase& base() const { return base_; }
  Outcome takeOutcome() { return std::exchange(outcome_, Outcome{}); }
  const std::string& node() const { return node_; }

 private:
  void onState(const GateState::ConstPtr& msg) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      states_.push_back(*msg);
    }
    answered_.notify_all();
  }
  std::size_t stateCount() {
    std::lock_guard<std::mutex> lock(mutex_);
    return states_.size();
  }

  std::string node_, odom_frame_, base_frame_;
  core::SimulatedBase base_;
  Outcome outcome_;
  ros::Publisher scan_pub_, odom_pub_, cmd_pub_;
  ros::Subscriber state_sub_;
  ros::ServiceClient check_;
  tf2_ros::TransformBroadcaster tf_;
  std::mutex mutex_;
  std::condition_variable answered_;
  std::vector<GateState> states_;
};

/// The client: the clock, the two robots, and the movers placed relative to each robot.
class Crossings : public ::testing::Test {
 protected:
  void SetUp() override {
    spinner_.start();
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 1, true);
    publishClock();
    robots_.push_back(std::make_unique<Robot>(nh_, "/crossings_tracked", "tracked", t_));
    robots_.push_back(std::make_unique<Robot>(nh_, "/crossings_untracked", "untracked", t_));
    for (const auto& robot : robots_) {
      ASSERT_TRUE(test::waitUntil([&] { return robot->connected(); }, 60.0)) << robot->node();
    }
    // ~gate_state is latched: its last message arrives on connecting, and must not be taken
    // for the answer to the first command.
    std::this_thread::sleep_for(std::chrono::seconds(1));
  }

  void publishClock() {
    rosgraph_msgs::Clock clock;
    clock.clock = ros::Time(kClockStart + t_);
    clock_pub_.publish(clock);
  }

  /// Runs the world for `duration` [s]: `moverAt(robot start x [m], time since the stretch began
  /// [s])` places the mover in odom, the robots are commanded `vx` [m/s]; after each command,
  /// `afterCommand(time since the stretch began)` if given.
  void run(double duration, double vx, const std::function<Mover(double, double)>& moverAt,
           const std::function<void(double)>& afterCommand = {}) {
    std::vector<double> start_x;
    for (const auto& robot : robots_) start_x.push_back(robot->position().x());
    const double begin = t_;
    for (; t_ - begin < duration - 1e-9; t_ += kScanPeriod) {
      const double since = t_ - begin;
      std::vector<Mover> movers;
      for (std::size_t i = 0; i < robots_.size(); ++i) {
        robots_[i]->advanceTo(t_, [&](double t) { return moverAt(start_x[i], t - begin); });
        movers.push_back(moverAt(start_x[i], since));
      }
      publishClock();
      for (std::size_t i = 0; i < robots_.size(); ++i) {
        test::World world = corridor();
        if (movers[i].present) world.pillars.push_back({movers[i].centre, movers[i].radius});
        robots_[i]->publishSensors(ros::Time(kClockStart + t_), world, ++seed_);
      }
      // The scans and tf travel on connections of their own: a head start over the command.
      std::this_thread::sleep_for(std::chrono::milliseconds(4));
      if (step_++ % 2 != 0) continue;
      std::vector<std::size_t> before;
      for (const auto& robot : robots_) before.push_back(robot->sendCommand(vx));
      for (std::size_t i = 0; i < robots_.size(); ++i) {
        ASSERT_TRUE(robots_[i]->waitForAnswer(before[i], t_))
            << robots_[i]->node() << ": no ~gate_state for the command";
      }
      if (afterCommand) afterCommand(since);
    }
  }

  /// A corridor 8 m wide along x, long enough for every crossing.
  static test::World corridor() {
    test::World world;
    world.walls.push_back({{-20.0, -4.0}, {3000.0, -4.0}});
    world.walls.push_back({{-20.0, 4.0}, {3000.0, 4.0}});
    return world;
  }

  static constexpr double kClockStart = 1000.0;  // [s] the simulated clock at t = 0
  ros::NodeHandle nh_;
  ros::AsyncSpinner spinner_{2};
  ros::Publisher clock_pub_;
  std::vector<std::unique_ptr<Robot>> robots_;  // [0] tracked, [1] untracked
  static inline double t_ = 0.0;                // [s] of the run, on across tests (no time jumps)
  std::uint64_t step_{0}, seed_{0};
};

struct Crossing {
  double ahead{3.0};   ///< [m] where the person's path crosses the robot's, from its start
  double speed{1.0};   ///< [m/s] the person's, toward +y
  double offset{0.0};  ///< [m] the person's lead when the robot would reach the path at kCruise
};

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

TEST_F(Crossings, APersonCrossingIsNeverHitWhileTheBaseMovesWhenTheNodeTracksItsScans) {
  const int count = ros::NodeHandle("~").param("crossings", 6);
  ASSERT_GT(count, 0);
  // The crossings of test_tracked_crossings.cpp: the path 2-4 m ahead, the person at 0.5-1.5 m/s,
  // arriving up to 1 m early or late (seeded).
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> ahead(2.0, 4.0), speed(0.5, 1.5), offset(-1.0, 1.0);
  const auto nobody = [](double, double) { return Mover{}; };
  std::vector<Outcome> totals(robots_.size());
  std::vector<int> contacts(robots_.size(), 0);
  std::vector<std::vector<double>> closest(robots_.size());
  for (int i = 0; i < count; ++i) {
    const Crossing crossing{ahead(random), speed(random), offset(random)};
    // A run-up of 2 s in the empty corridor: each base back at cruise, old tracks gone.
    run(2.0, kCruise, nobody);
    if (HasFatalFailure()) return;
    for (const auto& robot : robots_) robot->takeOutcome();
    const double meet = crossing.ahead / kCruise;
    // Until the person is 1.5 m past the robot's line.
    const double duration = meet + (1.5 - crossing.offset) / crossing.speed;
    run(duration, kCruise, [&](double start_x, double since) {
      return Mover{true,
                   {start_x + crossing.ahead, crossing.offset + crossing.speed * (since - meet)},
                   kPersonRadius};
    });
    if (HasFatalFailure()) return;
    std::printf("crossing %2d: %.2f m ahead at %.2f m/s, offset %+.2f m", i, crossing.ahead,
                crossing.speed, crossing.offset);
    for (std::size_t r = 0; r < robots_.size(); ++r) {
      const Outcome outcome = robots_[r]->takeOutcome();
      contacts[r] += outcome.contact_while_moving;
      closest[r].push_back(outcome.closest);
      std::printf(" | %s: %s, closest %.3f m, %s", r == 0 ? "tracked" : "untracked",
                  outcome.contact_while_moving ? "CONTACT while moving" : "no contact while moving",
                  outcome.closest, outcome.actionList().c_str());
    }
    std::printf("\n");
    std::fflush(stdout);
  }
  std::printf("crossings table:\n");
  std::printf("| %d crossings through the node | tracked | untracked |\n", count);
  std::printf("|---|---|---|\n");
  std::printf("| base moving at contact | %d | %d |\n", contacts[0], contacts[1]);
  std::printf("| closest approach, min [m] | %.3f | %.3f |\n",
              *std::min_element(closest[0].begin(), closest[0].end()),
              *std::min_element(closest[1].begin(), closest[1].end()));
  std::printf("| closest approach, median [m] | %.3f | %.3f |\n", median(closest[0]),
              median(closest[1]));
  std::fflush(stdout);
  EXPECT_EQ(contacts[0], 0) << "the tracking node's robot hit the person while moving";
  // Not a vacuous scene: predicted standing, the same crossings are hit.
  EXPECT_GT(contacts[1], 0) << "the node without tracking never hit the person";
}

TEST_F(Crossings, ACartStartingToRollTowardTheRobotIsReportedMovingWithinHalfASecond) {
  // Both robots brought to rest, then a cart 3 m ahead stands for 1 s and rolls toward them at
  // 1 m/s. Reported moving: the node predicts a contact of the standing robot with it
  // (~check_collisions, prediction_horizon 5 s), which a standing cart cannot cause.
  constexpr double kCartRadius = 0.3, kCartSpeed = 1.0, kStand = 1.0;
  run(2.0, 0.0, [](double, double) { return Mover{}; });
  if (HasFatalFailure()) return;
  for (const auto& robot : robots_) ASSERT_FALSE(robot->base().moving()) << robot->node();
  const auto cart = [&](double start_x, double since) {
    const double rolled = kCartSpeed * std::max(0.0, since - kStand);
    return Mover{true, {start_x + 3.0 - rolled, 0.0}, kCartRadius};
  };
  const auto cartPredicted = [&](Robot& robot) -> std::optional<double> {
    const auto predicted = robot.predicted();
    if (!predicted) return std::nullopt;
    for (const PredictedContact& p : *predicted) {
      if (p.name_a == "body" || p.name_b == "body") return p.time;
    }
    return std::nullopt;
  };
  std::optional<double> reported_after;  // [s] after the cart began to roll
  std::optional<double> untracked_reported_after;
  double time_at_one_second = -1.0;  // [s] predicted, 1 s after the roll began
  run(kStand + 1.5, 0.0, cart, [&](double since) {
    const std::optional<double> tracked = cartPredicted(*robots_[0]);
    const std::optional<double> untracked = cartPredicted(*robots_[1]);
    if (since < kStand) {
      EXPECT_FALSE(tracked) << "the standing cart predicted to touch at " << *tracked << " s";
      return;
    }
    if (tracked && !reported_after) reported_after = since - kStand;
    if (untracked && !untracked_reported_after) untracked_reported_after = since - kStand;
    if (since >= kStand + 1.0 - 1e-9 && time_at_one_second < 0.0 && tracked) {
      time_at_one_second = *tracked + (since - kStand - 1.0);  // as seen at exactly 1 s
    }
  });
  if (HasFatalFailure()) return;
  ASSERT_TRUE(reported_after.has_value()) << "the rolling cart was never reported moving";
  std::printf(
      "rolling cart: reported moving %.3f s after it began to roll; untracked: %s\n",
      *reported_after,
      untracked_reported_after ? std::to_string(*untracked_reported_after).c_str() : "never");
  EXPECT_LE(*reported_after, 0.5);
  EXPECT_FALSE(untracked_reported_after.has_value()) << "a node without tracking saw it move";
  // 1 s into the roll the gap is 1.45 m: at 1 m/s contact is 1.45 s away.
  const double truth = (3.0 - kCartSpeed * 1.0 - kRobotRadius - kCartRadius) / kCartSpeed;
  EXPECT_NEAR(time_at_one_second, truth, 0.3 * truth);
}

}  // namespace
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_crossings");
  return RUN_ALL_TESTS();
}
