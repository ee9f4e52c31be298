# Reliability rostests (test/reliability/): hostile requests to every service and the ~obstacles
# topic, bad configuration files started through the launch file, and the load test. Included
# from CMakeLists.txt inside if(CATKIN_ENABLE_TESTING), after cmake/ros_tests.cmake, whose
# ellipse_collision_add_rostest() builds each client (links the ROS layer, depends on the node).
find_package(rostest REQUIRED)

ellipse_collision_add_rostest(test_hostile_requests test/reliability/hostile_requests.test
  test/reliability/test_hostile_requests.cpp)

ellipse_collision_add_rostest(test_bad_startup test/reliability/bad_startup.test
  test/reliability/test_bad_startup.cpp)
target_compile_definitions(test_bad_startup PRIVATE
  ELLIPSE_COLLISION_SOURCE_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

# 60 s of load by default; a quick run: rostest $PWD/test/reliability/load.test duration:=10
ellipse_collision_add_rostest(test_load test/reliability/load.test
  test/reliability/test_load.cpp)
