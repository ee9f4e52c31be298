#include "ellipse_collision/ros/tf_listener.h"

namespace ellipse_collision {

TfListener::TfListener(tf2_ros::Buffer& buffer) {
  // The listener's subscriptions (/tf and /tf_static, as it names them) deliver into queue_.
  ros::NodeHandle nh;
  nh.setCallbackQueue(&queue_);
  listener_ = std::make_unique<tf2_ros::TransformListener>(buffer, nh, /*spin_thread=*/false);
  // As the listener does for its own thread: lookups may wait for a transform.
  buffer.setUsingDedicatedThread(true);
  thread_ = std::thread([this] {
    // callAvailable() returns as soon as a message is queued, or disable() is called; the
    // timeout is only a backstop.
    while (queue_.isEnabled()) queue_.callAvailable(ros::WallDuration(1.0));
  });
}

TfListener::~TfListener() {
  queue_.disable();  // wakes the thread, which ends
  thread_.join();
  listener_.reset();  // unsubscribes before the queue goes
}

}  // namespace ellipse_collision
