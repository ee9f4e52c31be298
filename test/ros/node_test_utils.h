#pragma once

// Helpers shared by the rostest clients, which run an AsyncSpinner so that subscriptions keep
// filling while a test waits or calls a service.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <chrono>
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

inline EllipseMsg ellipseMsg(const std::string& name, const std::string& frame, double x, double y,
                             double radius_x, double radius_y, double angle = 0.0) {
  EllipseMsg msg;
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
