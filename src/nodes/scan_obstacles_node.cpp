#include "ellipse_collision/ros/param_reading.h"
#include "ellipse_collision/ros/scan_obstacles.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "scan_obstacles");
  ros::NodeHandle nh, private_nh("~");  // alive past the catch: logging needs them
  try {
    ellipse_collision::ScanObstaclesNode node(nh, private_nh);
    ros::spin();
  } catch (const ellipse_collision::ConfigError& error) {
    ROS_FATAL_STREAM("scan_obstacles: invalid configuration: " << error.what());
    return 1;
  }
  return 0;
}
