// The velocity gate through ROS: a client publishes geometry_msgs/Twist commands on the running
// node's ~cmd_vel_in, one at a time, and times each until its ~cmd_vel_out arrives (loopback TCP,
// no Nagle), with 1,000 / 10,000 / 100,000 obstacles stored on a warehouse floor (one per 4 m^2,
// a clearing about the robot) and bench/gate_roundtrip.yaml's 20 links. The ROS floor beside it:
// the same commands through a relay that republishes each Twist at once (this program with
// --relay IN OUT, in a process of its own), in alternating blocks so that both share the
// machine's noise. The client moves base_link in odom a little before every command (tf), so
// the node places the links anew each time. scripts/benchmark.sh starts roscore, the node and
// the relay.
//
//   bench_gate_roundtrip [--commands N] [--sizes 1000,10000,100000] [--node /ellipse_collision]
//                        [--relay-in /relay/in --relay-out /relay/out]
//   bench_gate_roundtrip --relay IN OUT
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "ellipse_collision/ros/messages.h"
#include "floor_obstacles.h"

namespace ellipse_collision {
namespace {

using Clock = std::chrono::steady_clock;

struct Options {
  int commands{2000};
  std::vector<int> sizes{1000, 10000, 100000};
  std::string node{"/ellipse_collision"};
  std::string relay_in;
  std::string relay_out;
};

bool parseOptions(int argc, char** argv, Options* options) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--commands") {
      options->commands = std::atoi(value.c_str());
    } else if (key == "--node") {
      options->node = value;
    } else if (key == "--relay-in") {
      options->relay_in = value;
    } else if (key == "--relay-out") {
      options->relay_out = value;
    } else if (key == "--sizes") {
      options->sizes.clear();
      std::stringstream list(value);
      std::string item;
      while (std::getline(list, item, ',')) options->sizes.push_back(std::atoi(item.c_str()));
    } else {
      return false;
    }
  }
  return options->commands > 0 && !options->sizes.empty();
}

/// Times one command after another through `in` -> `out`.
class RoundTrip {
 public:
  RoundTrip(ros::NodeHandle& nh, const std::string& in, const std::string& out)
      : pub_(nh.advertise<geometry_msgs::Twist>(in, 1)),
        sub_(nh.subscribe(out, 1, &RoundTrip::onOutput, this, ros::TransportHints().tcpNoDelay())) {}
  bool connect() {
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    while (Clock::now() < deadline) {
      if (pub_.getNumSubscribers() > 0 && sub_.getNumPublishers() > 0) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }
  /// Microseconds from publishing to the answer; negative when none came within a second.
  double once(double vx) {
    // base_link moves about odom's origin, inside the clearing.
    ++step_;
    geometry_msgs::TransformStamped t;
    t.header.stamp = ros::Time::now();
    t.header.frame_id = "odom";
    t.child_frame_id = "base_link";
    t.transform.translation.x = 0.3 * std::sin(0.01 * step_);
    t.transform.translation.y = 0.3 * std::cos(0.013 * step_);
    t.transform.rotation.z = std::sin(0.01 * step_);
    t.transform.rotation.w = std::cos(0.01 * step_);
    tf_.sendTransform(t);
    const int before = received_.load();
    geometry_msgs::Twist cmd;
    cmd.linear.x = vx;
    cmd.angular.z = 0.3;
    const auto start = Clock::now();
    pub_.publish(cmd);
    while (received_.load() == before) {
      if (Clock::now() - start > std::chrono::seconds(1)) return -1.0;
      std::this_thread::yield();
    }
    return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
  }

 private:
  void onOutput(const geometry_msgs::Twist::ConstPtr&) { ++received_; }
  ros::Publisher pub_;
  ros::Subscriber sub_;
  std::atomic<int> received_{0};
  tf2_ros::TransformBroadcaster tf_;
  int step_{0};
};

/// One obstacle per 4 m^2 in odom, a clearing of 1.5 m about the robot.
std::vector<Ellipse> warehouse(int count) {
  std::vector<Ellipse> obstacles;
  int i = 0;
  for (const bench::FloorObstacle& o :
       bench::floorObstacles(count, std::sqrt(static_cast<double>(count)), 1.5, 5)) {
    Ellipse e;
    e.name = "obstacle_" + std::to_string(i++);
    e.frame_id = "odom";
    e.x = o.x;
    e.y = o.y;
    e.angle = o.angle;
    e.radius_x = o.radius_x;
    e.radius_y = o.radius_y;
    obstacles.push_back(e);
  }
  return obstacles;
}

double quantile(std::vector<double> samples, double q) {
  std::sort(samples.begin(), samples.end());
  return samples[std::min(samples.size() - 1, static_cast<std::size_t>(q * samples.size()))];
}

int run(const Options& options) {
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  RoundTrip gate(nh, options.node + "/cmd_vel_in", options.node + "/cmd_vel_out");
  std::unique_ptr<RoundTrip> relay;
  if (!options.relay_in.empty()) relay.reset(new RoundTrip(nh, options.relay_in, options.relay_out));
  ros::ServiceClient add = nh.serviceClient<AddObstacles>(options.node + "/add_obstacles");
  ros::ServiceClient remove = nh.serviceClient<RemoveObstacles>(options.node + "/remove_obstacles");
  if (!add.waitForExistence(ros::Duration(30.0)) || !gate.connect() ||
      (relay && !relay->connect())) {
    std::fprintf(stderr, "bench_gate_roundtrip: the node (or the relay) did not come up\n");
    return 1;
  }
  std::printf("%-10s %10s %10s %10s %12s %12s %8s\n", "obstacles", "gate p50", "gate p99",
              "gate max", "relay p50", "relay p99", "p50 x");
  for (const int size : options.sizes) {
    AddObstacles srv;
    srv.request.obstacles = warehouse(size);
    if (!add.call(srv) || !srv.response.success) {
      std::fprintf(stderr, "bench_gate_roundtrip: ~add_obstacles failed: %s\n",
                   srv.response.message.c_str());
      return 1;
    }
    std::vector<double> through_gate, through_relay;
    // Alternating blocks of 50, after 100 unmeasured commands of each.
    for (int i = 0; i < 100; ++i) {
      gate.once(0.5);
      if (relay) relay->once(0.5);
    }
    while (static_cast<int>(through_gate.size()) < options.commands) {
      for (int i = 0; i < 50; ++i) {
        const double us = gate.once(0.2 + 0.001 * (through_gate.size() % 500));
        if (us < 0) {
          std::fprintf(stderr, "bench_gate_roundtrip: no ~cmd_vel_out within 1 s\n");
          return 1;
        }
        through_gate.push_back(us);
      }
      for (int i = 0; relay && i < 50; ++i) through_relay.push_back(relay->once(0.5));
    }
    const double relay_p50 = through_relay.empty() ? 0.0 : quantile(through_relay, 0.5);
    std::printf("%-10d %8.0f us %8.0f us %8.0f us %9.0f us %9.0f us %8.2f\n", size,
                quantile(through_gate, 0.5), quantile(through_gate, 0.99),
                quantile(through_gate, 1.0), relay_p50,
                through_relay.empty() ? 0.0 : quantile(through_relay, 0.99),
                relay_p50 > 0 ? quantile(through_gate, 0.5) / relay_p50 : 0.0);
    std::fflush(stdout);
    RemoveObstacles gone;
    for (const Ellipse& e : srv.request.obstacles) gone.request.names.push_back(e.name);
    if (!remove.call(gone) || !gone.response.success) return 1;
  }
  return 0;
}

}  // namespace
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  ros::init(argc, argv, "bench_gate_roundtrip", ros::init_options::AnonymousName);
  if (argc == 4 && std::string(argv[1]) == "--relay") {
    // The floor: a node that republishes each Twist as it comes.
    ros::NodeHandle nh;
    ros::Publisher out = nh.advertise<geometry_msgs::Twist>(argv[3], 1);
    ros::Subscriber in = nh.subscribe<geometry_msgs::Twist>(
        argv[2], 1, [&out](const geometry_msgs::Twist::ConstPtr& msg) { out.publish(*msg); },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
    ros::spin();
    return 0;
  }
  ellipse_collision::Options options;
  if (!ellipse_collision::parseOptions(argc, argv, &options)) {
    std::fprintf(stderr,
                 "usage: %s [--commands N] [--sizes 1000,10000] [--node /ellipse_collision] "
                 "[--relay-in IN --relay-out OUT] | --relay IN OUT\n",
                 argv[0]);
    return 2;
  }
  return ellipse_collision::run(options);
}
