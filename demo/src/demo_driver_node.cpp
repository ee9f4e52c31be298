// demo_driver: moves the demo robot (demo/urdf/demo_robot.urdf) and a moving obstacle; see
// demo/src/demo_driver.h and demo/launch/demo.launch.
#include "demo_driver.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "demo_driver");
  // Declared outside the try: destroying the last NodeHandle shuts ROS down, and its log with it.
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    ellipse_collision::DemoDriver driver(nh, private_nh);
    ros::spin();
  } catch (const ellipse_collision::DemoConfigError& error) {
    ROS_FATAL_STREAM("demo_driver: invalid configuration: " << error.what());
    return 1;
  }
  return 0;
}
