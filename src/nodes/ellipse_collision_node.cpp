#include <malloc.h>

#include <optional>

#include "ellipse_collision/ros/collision_node.h"

int main(int argc, char** argv) {
  // Keep 16 MB free at the heap top: each cycle's marker array is freed whole, and glibc's default
  // returned it to the kernel and page-faulted it back the next cycle (1,000 streamed obstacles:
  // 3,600-5,100 minor faults/s and a tenth to a fifth of the node's CPU; with the pad ~12/s).
  mallopt(M_TOP_PAD, 16 << 20);
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
