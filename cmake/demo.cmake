# Demo robot: driver node and install rules. Included from CMakeLists.txt after the ROS layer.
# Only demo_driver needs sensor_msgs and std_srvs; finding them here keeps catkin_LIBRARIES as the
# main find_package(catkin) left it.
find_package(sensor_msgs REQUIRED)
find_package(std_srvs REQUIRED)

add_executable(demo_driver
  src/tools/demo_driver.cpp
  src/ros/demo_driver.cpp
  src/ros/demo_trajectory.cpp)
target_include_directories(demo_driver PRIVATE
  src/ros ${sensor_msgs_INCLUDE_DIRS} ${std_srvs_INCLUDE_DIRS})
target_link_libraries(demo_driver ellipse_collision_ros)
target_compile_options(demo_driver PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(demo_driver ${PROJECT_NAME}_generate_messages_cpp)

install(TARGETS demo_driver RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
# launch/ and config/ are installed by CMakeLists.txt.
install(DIRECTORY urdf rviz DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
install(PROGRAMS scripts/demo.sh DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
