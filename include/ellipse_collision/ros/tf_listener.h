#pragma once

#include <ros/callback_queue.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <thread>

namespace ellipse_collision {

/// Fills `buffer` from /tf and /tf_static on a thread of its own, like tf2_ros::TransformListener's
/// own thread (lookups may wait for a transform while the node's callbacks run), but that thread
/// sleeps until a tf message arrives: tf2_ros' polls its queue 100 times a second, 0.4 % of a
/// core on the shared machine for a node that has nothing else to do. The buffer must outlive it.
class TfListener {
 public:
  explicit TfListener(tf2_ros::Buffer& buffer);
  ~TfListener();
  TfListener(const TfListener&) = delete;
  TfListener& operator=(const TfListener&) = delete;

 private:
  ros::CallbackQueue queue_;
  std::unique_ptr<tf2_ros::TransformListener> listener_;
  std::thread thread_;
};

}  // namespace ellipse_collision
