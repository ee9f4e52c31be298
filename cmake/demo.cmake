# The demo (demo/): a user of the package, not part of it. Its driver node, URDF, configuration,
# launch file and rviz view live in demo/. Only demo_driver needs sensor_msgs and std_srvs;
# finding them here keeps catkin_LIBRARIES as the main find_package(catkin) left it.
find_package(sensor_msgs REQUIRED)
find_package(std_srvs REQUIRED)

add_executable(demo_driver
  demo/src/demo_driver_node.cpp
  demo/src/demo_driver.cpp
  demo/src/demo_arm_guard.cpp
  demo/src/demo_log_on_change.cpp
  demo/src/demo_base_control.cpp
  demo/src/demo_scanner.cpp
  demo/src/demo_world.cpp
  demo/src/demo_trajectory.cpp)
target_include_directories(demo_driver PRIVATE
  demo/src ${sensor_msgs_INCLUDE_DIRS} ${std_srvs_INCLUDE_DIRS})
target_link_libraries(demo_driver ellipse_collision_ros)
target_compile_options(demo_driver PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(demo_driver ${PROJECT_NAME}_generate_messages_cpp)

install(TARGETS demo_driver RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
install(DIRECTORY demo/config demo/launch demo/urdf demo/rviz
  DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/demo)
install(PROGRAMS scripts/demo.sh DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
