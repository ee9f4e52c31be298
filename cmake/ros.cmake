# Thin ROS layer (include/ellipse_collision/ros/, src/ros/, src/nodes/): parameters, message
# conversion, tf, advertise and publish. ROS include directories are added per target, so the core
# and the application layer never see them.
add_library(ellipse_collision_ros
  ${ELLIPSE_COLLISION_PARAMETER_SOURCES}
  src/ros/collision_markers.cpp
  src/ros/collision_node.cpp
  src/ros/conversions.cpp
  src/ros/fleet_publisher.cpp
  src/ros/gate_markers.cpp
  src/ros/incident_bag.cpp
  src/ros/incident_writer.cpp
  src/ros/reconfigure.cpp
  src/ros/scan_obstacles.cpp
  src/ros/source_subscribers.cpp
  src/ros/tf_listener.cpp
  src/ros/tf_lookup.cpp
  src/ros/urdf_links.cpp)
target_include_directories(ellipse_collision_ros PUBLIC include ${catkin_INCLUDE_DIRS})
target_link_libraries(ellipse_collision_ros PUBLIC ellipse_collision_app ${catkin_LIBRARIES}
  PRIVATE ${ASSIMP_LIBRARIES})
target_compile_options(ellipse_collision_ros PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(ellipse_collision_ros
  ${PROJECT_NAME}_generate_messages_cpp ${PROJECT_NAME}_gencfg ${catkin_EXPORTED_TARGETS})

add_executable(ellipse_collision_node src/nodes/ellipse_collision_node.cpp)
target_link_libraries(ellipse_collision_node ellipse_collision_ros)
target_compile_options(ellipse_collision_node PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(ellipse_collision_node ${PROJECT_NAME}_generate_messages_cpp)

# scan_obstacles: obstacle ellipses from LaserScan and PointCloud2.
add_executable(scan_obstacles src/nodes/scan_obstacles_node.cpp)
target_link_libraries(scan_obstacles ellipse_collision_ros)
target_compile_options(scan_obstacles PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(scan_obstacles ${PROJECT_NAME}_generate_messages_cpp)

# The collision node and scan_obstacles as nodelets (nodelet_plugins.xml, exported in
# package.xml): scan -> obstacle ellipses -> check in one process, messages passed as pointers.
add_library(ellipse_collision_nodelets
  src/nodelets/collision_nodelet.cpp
  src/nodelets/scan_obstacles_nodelet.cpp)
target_include_directories(ellipse_collision_nodelets PRIVATE ${nodelet_INCLUDE_DIRS})
target_link_libraries(ellipse_collision_nodelets ellipse_collision_ros ${nodelet_LIBRARIES})
target_compile_options(ellipse_collision_nodelets PRIVATE ${ELLIPSE_COLLISION_WARNINGS})

# fit_link_ellipses: a URDF's link ellipses as a `links:` block for the configuration.
add_executable(fit_link_ellipses src/tools/fit_link_ellipses.cpp)
target_link_libraries(fit_link_ellipses ellipse_collision_ros)
target_compile_options(fit_link_ellipses PRIVATE ${ELLIPSE_COLLISION_WARNINGS})

# incident_replay: an incident bag's decisions judged again (doc/incidents.md, "Replay");
# incident_report --replay runs it.
add_executable(incident_replay src/tools/incident_replay.cpp)
target_link_libraries(incident_replay ellipse_collision_ros)
target_compile_options(incident_replay PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(incident_replay ${PROJECT_NAME}_generate_messages_cpp)

install(TARGETS ellipse_collision_ros ellipse_collision_nodelets ellipse_collision_node scan_obstacles
  fit_link_ellipses incident_replay
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
install(DIRECTORY ${ELLIPSE_COLLISION_REAL_SOURCE_DIR}/launch ${ELLIPSE_COLLISION_REAL_SOURCE_DIR}/config
  DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
install(FILES ${ELLIPSE_COLLISION_REAL_SOURCE_DIR}/nodelet_plugins.xml
  DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
catkin_install_python(PROGRAMS examples/check_collisions_client.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
# The page a person reads of an incident bag (doc/incidents.md): rosrun ellipse_collision
# incident_report BAG.
catkin_install_python(PROGRAMS scripts/incident_report
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
