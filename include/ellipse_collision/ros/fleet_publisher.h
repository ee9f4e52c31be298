#pragma once

#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/collision_monitor.h"
#include "ellipse_collision/app/fleet_footprint.h"
#include "ellipse_collision/ros/node_config.h"

namespace ellipse_collision {

/// fleet/: this robot's links in fleet/frame on fleet/topic at fleet/rate, each with its velocity
/// over the last interval (app::FleetFootprint), computed only while someone listens.
class FleetPublisher {
 public:
  /// Advertises and starts the timer at once. `config`, `monitor` and `tf_buffer` must outlive
  /// this.
  FleetPublisher(ros::NodeHandle nh, const NodeConfig& config, const app::CollisionMonitor& monitor,
                 const tf2_ros::Buffer& tf_buffer);

  /// For /diagnostics: whether the last footprint could not be sent, a message saying what is
  /// published (or why not), and its values.
  struct Status {
    bool failing{false};
    std::string message;
    std::vector<std::pair<std::string, std::string>> values;
  };
  Status status() const;

 private:
  void onTimer(const ros::TimerEvent& event);

  const NodeConfig& config_;
  const app::CollisionMonitor& monitor_;
  const tf2_ros::Buffer& tf_buffer_;
  ros::Publisher publisher_;
  ros::Timer timer_;
  app::FleetFootprint footprint_;
  std::string error_;  ///< why the last footprint was not sent ("" = it was)
  std::size_t sent_{0};
};

}  // namespace ellipse_collision
