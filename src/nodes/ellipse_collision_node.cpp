#include <optional>

#include "ellipse_collision/ros/collision_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "ellipse_collision");
  // Kept alive past the catch: destroying the last handle shuts ROS down, logging included.
  ros::NodeHandle nh, private_nh("~");
  // --check-config: only validate the parameters, as the node does, then idle (the launch
  // file's required guard).
  const bool check_only = std::string(argv[argc - 1]) == "--check-config";
  try {
    std::optional<ellipse_collision::CollisionNode> node;
    if (check_only) ellipse_collision::loadCollisionNodeConfig(private_nh);
    else node.emplace(nh, private_nh);
    ros::spin();
  } catch (const ellipse_collision::ConfigError& error) {
    ROS_FATAL_STREAM("ellipse_collision: invalid configuration: " << error.what());
    return 1;
  }
  return 0;
}
