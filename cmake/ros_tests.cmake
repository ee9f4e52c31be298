# rostest and ROS-layer gtests.
