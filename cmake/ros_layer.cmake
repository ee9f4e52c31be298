# ROS layer targets (node, conversions, markers).
