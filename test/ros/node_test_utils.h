#pragma once

// Helpers shared by the rostest clients, which run an AsyncSpinner so that subscriptions keep
// filling while a test waits or calls a service.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sys/wait.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "ellipse_collision/ros/messages.h"

namespace ellipse_collision {
namespace test {

/// The node under test, as named in the .test files.
inline std::string nodeTopic(const std::string& name) { return "/ellipse_collision/" + name; }

inline Ellipse ellipseMsg(const std::string& name, const std::string& frame, double x, double y,
                             double radius_x, double radius_y, double angle = 0.0) {
  Ellipse msg;
  msg.name = name;
  msg.frame_id = frame;
  msg.x = x;
  msg.y = y;
  msg.angle = angle;
  msg.radius_x = radius_x;
  msg.radius_y = radius_y;
  msg.padding = 0.0;
  return msg;
}

/// ellipseMsg() made an ellipsoid: semi-axis radius_z [m] and a tilt in the frame (roll, pitch
/// [rad], orientation Rz(angle) Ry(pitch) Rx(roll)); centre height 0.
inline Ellipse ellipsoidMsg(const std::string& name, const std::string& frame, double x, double y,
                            double radius_x, double radius_y, double radius_z, double roll,
                            double pitch = 0.0) {
  Ellipse msg = ellipseMsg(name, frame, x, y, radius_x, radius_y);
  msg.radius_z = radius_z;
  msg.roll = roll;
  msg.pitch = pitch;
  return msg;
}

/// Polls `condition` every 20 ms for at most `timeout_s` seconds of wall time.
inline bool waitUntil(const std::function<bool()>& condition, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return condition();
}

inline const CollisionPair* findPair(const std::vector<CollisionPair>& pairs, const std::string& a,
                                     const std::string& b) {
  for (const CollisionPair& pair : pairs) {
    if (pair.name_a == a && pair.name_b == b) return &pair;
  }
  return nullptr;
}

inline const ClearancePair* findWarning(const std::vector<ClearancePair>& pairs,
                                        const std::string& a, const std::string& b) {
  for (const ClearancePair& pair : pairs) {
    if (pair.name_a == a && pair.name_b == b) return &pair;
  }
  return nullptr;
}

inline bool mentions(const std::vector<CollisionPair>& pairs, const std::string& name) {
  for (const CollisionPair& pair : pairs) {
    if (pair.name_a == name || pair.name_b == name) return true;
  }
  return false;
}

/// Calls the node's three services; every call expects the node to still serve it. A fixture
/// derives from it and connects in SetUp, once the services are up.
class NodeServiceClient {
 public:
  /// `persistent`: one connection per service for every call, what a client calling many times a
  /// second should use. A new connection per call (the default) loses a call now and then under
  /// load in roscpp itself: the client can drop the connection on the server's hang-up before it
  /// reads the answer (ros/ros_comm#1976); a persistent connection is never hung up. A node that
  /// restarts needs new connections (respawn.test keeps the default).
  void connectServices(ros::NodeHandle& nh, bool persistent = false) {
    check_ = nh.serviceClient<CheckCollisions>(nodeTopic("check_collisions"), persistent);
    add_ = nh.serviceClient<AddObstacles>(nodeTopic("add_obstacles"), persistent);
    remove_ = nh.serviceClient<RemoveObstacles>(nodeTopic("remove_obstacles"), persistent);
  }

  /// What a test that drives the node through services and the ~obstacles topic needs first:
  /// the services up and connected, and `obstacles` advertised and subscribed to by the node.
  /// False if either took longer than 30 s.
  bool connectServicesAndObstacles(ros::NodeHandle& nh, ros::Publisher& obstacles,
                                   std::uint32_t queue_size, bool persistent = false) {
    if (!ros::service::waitForService(nodeTopic("check_collisions"), ros::Duration(30))) {
      return false;
    }
    connectServices(nh, persistent);
    obstacles = nh.advertise<EllipseArray>(nodeTopic("obstacles"), queue_size);
    return waitUntil([&obstacles] { return obstacles.getNumSubscribers() > 0; }, 30.0);
  }

  CheckCollisions::Response check(const std::vector<std::string>& names = {},
                                  const std::vector<Ellipse>& query = {},
                                  const ros::Time& stamp = ros::Time(0),
                                  const std::string& min_distance_of = "") {
    CheckCollisions srv;
    srv.request.names = names;
    srv.request.query = query;
    srv.request.stamp = stamp;
    srv.request.min_distance_of = min_distance_of;
    EXPECT_TRUE(check_.call(srv)) << "the node stopped serving ~check_collisions";
    return srv.response;
  }

  AddObstacles::Response add(const std::vector<Ellipse>& obstacles) {
    AddObstacles srv;
    srv.request.obstacles = obstacles;
    EXPECT_TRUE(add_.call(srv)) << "the node stopped serving ~add_obstacles";
    return srv.response;
  }

  RemoveObstacles::Response remove(const std::vector<std::string>& names) {
    RemoveObstacles srv;
    srv.request.names = names;
    EXPECT_TRUE(remove_.call(srv)) << "the node stopped serving ~remove_obstacles";
    return srv.response;
  }

  /// Whether the node stores an ellipse called `name` (a name filter on it is accepted).
  bool isStored(const std::string& name) { return check({name}).success; }

 private:
  ros::ServiceClient check_;
  ros::ServiceClient add_;
  ros::ServiceClient remove_;
};

/// Publishes `ellipses` in `frame`, stamped now, on the node's ~obstacles topic (`publisher`).
inline void publishObstacles(const ros::Publisher& publisher, const std::string& frame,
                             const std::vector<Ellipse>& ellipses) {
  EllipseArray msg;
  msg.header.frame_id = frame;
  msg.header.stamp = ros::Time::now();
  msg.ellipses = ellipses;
  publisher.publish(msg);
}

struct CommandRun {
  int exit_status{-1};  ///< the command's exit status; 124 when `timeout` stopped it
  std::string output;   ///< stdout and stderr
};

/// Runs `command` through the shell for at most `seconds` (SIGKILL 5 s later if it ignores
/// SIGTERM), capturing its output.
inline CommandRun runCommand(const std::string& command, int seconds) {
  CommandRun run;
  const std::string line = "timeout -k 5 " + std::to_string(seconds) + " " + command + " 2>&1";
  FILE* pipe = popen(line.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe)) run.output += buffer.data();
  const int status = pclose(pipe);
  run.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

/// Every message received on a topic since construction.
template <class M>
class Recorder {
 public:
  Recorder(ros::NodeHandle& nh, const std::string& topic) {
    subscriber_ = nh.subscribe<M>(topic, 1000, &Recorder::onMessage, this);
  }
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  std::vector<M> all() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return messages_;
  }
  std::size_t count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return messages_.size();
  }
  /// Waits until the newest message satisfies `predicate`; returns it through `out` if given.
  bool waitForLatest(const std::function<bool(const M&)>& predicate, double timeout_s,
                     M* out = nullptr) const {
    return waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          if (messages_.empty() || !predicate(messages_.back())) return false;
          if (out) *out = messages_.back();
          return true;
        },
        timeout_s);
  }
  /// Waits until any message from index `from` on satisfies `predicate`.
  bool waitForAny(const std::function<bool(const M&)>& predicate, double timeout_s,
                  std::size_t from = 0) const {
    return waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          for (std::size_t i = from; i < messages_.size(); ++i) {
            if (predicate(messages_[i])) return true;
          }
          return false;
        },
        timeout_s);
  }

 private:
  void onMessage(const boost::shared_ptr<const M>& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    messages_.push_back(*msg);
  }
  mutable std::mutex mutex_;
  std::vector<M> messages_;
  ros::Subscriber subscriber_;
};

/// Runs the tests of a rostest client with an AsyncSpinner.
inline int runRostestClient(int argc, char** argv, const std::string& node_name) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, node_name);
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  spinner.stop();
  ros::shutdown();
  return result;
}

}  // namespace test
}  // namespace ellipse_collision
