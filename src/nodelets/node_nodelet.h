#pragma once

#include <nodelet/nodelet.h>

#include <optional>

#include "ellipse_collision/ros/node_config.h"

namespace ellipse_collision {

/// A nodelet holding one of the package's node classes (CollisionNode, ScanObstaclesNode), built
/// from the nodelet's handles as its executable builds it from the node's. Its callbacks run on
/// the nodelet's single-threaded queue, so a node class written for ros::spin() stays
/// single-threaded in a manager with several worker threads.
///
/// A bad configuration: the ConfigError (which names the key) is logged under the nodelet's name
/// and rethrown. The manager catches it, unloads this nodelet and keeps running the others; its
/// load_nodelet service answers failure, so `nodelet load` exits with status 255 and a launch
/// that marks it required stops, as it does when the executable exits with status 1.
template <typename Node>
class NodeNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      node_.emplace(getNodeHandle(), getPrivateNodeHandle());
    } catch (const ConfigError& error) {
      NODELET_FATAL_STREAM(getName() << ": invalid configuration: " << error.what());
      throw;
    }
  }

  std::optional<Node> node_;
};

}  // namespace ellipse_collision
