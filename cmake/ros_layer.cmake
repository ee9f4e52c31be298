# ROS layer targets (node, conversions, markers). Included from CMakeLists.txt after the core.
# ROS include directories are added per target, so the core never sees them.

add_library(ellipse_collision_ros
  src/ros/collision_markers.cpp
  src/ros/collision_node.cpp
  src/ros/conversions.cpp
  src/ros/ellipse_registry.cpp
  src/ros/ellipse_spec.cpp
  src/ros/node_config.cpp
  src/ros/scene_placement.cpp
  src/ros/tf_lookup.cpp)
target_include_directories(ellipse_collision_ros PUBLIC include ${catkin_INCLUDE_DIRS})
target_link_libraries(ellipse_collision_ros PUBLIC ellipse_collision_core ${catkin_LIBRARIES})
target_compile_options(ellipse_collision_ros PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(ellipse_collision_ros
  ${PROJECT_NAME}_generate_messages_cpp ${catkin_EXPORTED_TARGETS})

add_executable(ellipse_collision_node src/ellipse_collision_node.cpp)
target_link_libraries(ellipse_collision_node ellipse_collision_ros)
target_compile_options(ellipse_collision_node PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(ellipse_collision_node ${PROJECT_NAME}_generate_messages_cpp)

install(TARGETS ellipse_collision_ros ellipse_collision_node
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
