#include "ellipse_collision/ros/collision_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "ellipse_collision");
  // Kept alive past the catch: destroying the last handle shuts ROS down, logging included.
  ros::NodeHandle nh, private_nh("~");
  try {
    ellipse_collision::CollisionNode node(nh, private_nh);
    ros::spin();
  } catch (const ellipse_collision::ConfigError& error) {
    ROS_FATAL_STREAM("ellipse_collision: invalid configuration: " << error.what());
    return 1;
  }
  return 0;
}
