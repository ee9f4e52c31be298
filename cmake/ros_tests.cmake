# rostest and ROS-layer gtests. Included from CMakeLists.txt inside if(CATKIN_ENABLE_TESTING).
find_package(rostest REQUIRED)

# ---- gtests that need no ROS master: conversions, parameters, registry, markers.
catkin_add_gtest(test_ros_units
  test/ros/test_conversions.cpp
  test/ros/test_node_config.cpp
  test/ros/test_ellipse_registry.cpp
  test/ros/test_collision_markers.cpp)
target_link_libraries(test_ros_units ellipse_collision_ros gtest_main)
target_compile_options(test_ros_units PRIVATE ${ELLIPSE_COLLISION_WARNINGS})

# ---- rostests: roscore, the real node, a tf helper and a gtest client.
# Helper node broadcasting the test frames; built with the tests only.
add_executable(tf_test_broadcaster EXCLUDE_FROM_ALL test/ros/tf_test_broadcaster.cpp)
target_include_directories(tf_test_broadcaster PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(tf_test_broadcaster ${catkin_LIBRARIES})
target_compile_options(tf_test_broadcaster PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
if(TARGET tests)
  add_dependencies(tests tf_test_broadcaster)
endif()

# Each client also needs the node, the helper and the Python messages (rosservice, rostopic).
function(ellipse_collision_add_rostest target launch_file)
  add_rostest_gtest(${target} ${launch_file} ${ARGN})
  target_link_libraries(${target} ellipse_collision_ros)
  target_compile_options(${target} PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
  target_compile_definitions(${target} PRIVATE
    ELLIPSE_COLLISION_NODE_BIN="$<TARGET_FILE:ellipse_collision_node>")
  add_dependencies(${target} ellipse_collision_node tf_test_broadcaster
    ${PROJECT_NAME}_generate_messages)
endfunction()

ellipse_collision_add_rostest(test_node_services test/ros/node_services.test
  test/ros/test_node_services.cpp)
ellipse_collision_add_rostest(test_node_topics test/ros/node_topics.test
  test/ros/test_node_topics.cpp)
ellipse_collision_add_rostest(test_node_cli test/ros/node_cli.test
  test/ros/test_node_cli.cpp)
ellipse_collision_add_rostest(test_bad_config test/ros/bad_config.test
  test/ros/test_bad_config.cpp)

# ---- every message and service type a user meets loads in Debian's Python (rosservice,
# rostopic, rospy): catches a missing python3-*-msgs package in scripts/setup.sh.
catkin_run_tests_target("python" "message_types" "python-message_types.xml"
  COMMAND "${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/python/check_message_types.py ${PROJECT_SOURCE_DIR} --junit ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/python-message_types.xml"
  DEPENDENCIES ${PROJECT_NAME}_generate_messages)

# ---- the rospy example client against the example configuration (a Python rostest).
add_rostest(test/ros/python_client.test
  DEPENDENCIES ellipse_collision_node ${PROJECT_NAME}_generate_messages)
