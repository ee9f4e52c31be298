#pragma once

// Helpers of the reliability rostests: the node's process id and resident memory, a tf broadcaster
// the test controls (frames that vanish or jump); running a command with a time limit
// (runCommand) comes from the shared rostest helpers.
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>

#include "../ros/node_test_utils.h"

namespace ellipse_collision {
namespace test {

/// Process id of the ROS node `node_name`, asked from the node itself through the master (its
/// XML-RPC getPid); -1 if it cannot be found.
inline int nodePid(const std::string& node_name) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  request[1] = node_name;
  if (!ros::master::execute("lookupNode", request, response, payload, false)) return -1;
  std::string uri = static_cast<std::string>(payload);  // http://host:port/
  const std::size_t host_start = uri.find("//") + 2;
  const std::size_t port_start = uri.find(':', host_start) + 1;
  const std::string host = uri.substr(host_start, port_start - 1 - host_start);
  const int port = std::stoi(uri.substr(port_start));
  XmlRpc::XmlRpcClient client(host.c_str(), port, "/");
  XmlRpc::XmlRpcValue args, result;
  args[0] = ros::this_node::getName();
  if (!client.execute("getPid", args, result) ||
      result.getType() != XmlRpc::XmlRpcValue::TypeArray || result.size() != 3) {
    return -1;
  }
  return static_cast<int>(result[2]);
}

/// Resident set size of process `pid` in KiB (VmRSS), or -1.
inline long residentKiB(int pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

/// Broadcasts frames relative to base_link at 50 Hz from its own thread, each of which the test
/// can move, stop (the frame vanishes from tf) or start again.
class TestFrames {
 public:
  TestFrames() : thread_([this] { run(); }) {}
  ~TestFrames() {
    running_ = false;
    thread_.join();
  }
  TestFrames(const TestFrames&) = delete;
  TestFrames& operator=(const TestFrames&) = delete;

  void set(const std::string& frame, double x, double y) {
    std::lock_guard<std::mutex> lock(mutex_);
    geometry_msgs::TransformStamped& t = frames_[frame];
    t.header.frame_id = "base_link";
    t.child_frame_id = frame;
    t.transform.translation.x = x;
    t.transform.translation.y = y;
    t.transform.translation.z = 0.0;
    t.transform.rotation.w = 1.0;
    stopped_.erase(frame);
  }
  void stop(const std::string& frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_[frame] = true;
  }

 private:
  void run() {
    while (running_) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        for (auto& named : frames_) {
          if (stopped_.count(named.first)) continue;
          named.second.header.stamp = ros::Time::now();
          broadcaster_.sendTransform(named.second);
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }

  std::mutex mutex_;
  std::map<std::string, geometry_msgs::TransformStamped> frames_;
  std::map<std::string, bool> stopped_;
  tf2_ros::TransformBroadcaster broadcaster_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

}  // namespace test
}  // namespace ellipse_collision
