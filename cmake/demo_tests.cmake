# Demo test: the whole demo with rviz in a virtual X server, judged from a screenshot.
# Included from CMakeLists.txt inside if(CATKIN_ENABLE_TESTING).
find_package(rostest REQUIRED)
find_package(std_srvs REQUIRED)
find_package(X11 REQUIRED)

catkin_add_executable_with_gtest(test_demo_screenshot EXCLUDE_FROM_ALL
  test/demo/test_demo_screenshot.cpp
  test/demo/rviz_top_down_view.cpp
  test/demo/screen_image.cpp)
target_include_directories(test_demo_screenshot PRIVATE
  test/ros ${std_srvs_INCLUDE_DIRS} ${X11_INCLUDE_DIR})
target_link_libraries(test_demo_screenshot ellipse_collision_ros ${X11_LIBRARIES})
target_compile_options(test_demo_screenshot PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(test_demo_screenshot ${PROJECT_NAME}_generate_messages_cpp)
if(TARGET tests)
  add_dependencies(tests test_demo_screenshot)
endif()

# add_rostest() with the command wrapped in xvfb-run: rviz needs an X display, and a private one
# of known size keeps the picture the same on every machine (and off the user's desktop).
# -a picks a free display number.
set(_demo_test test/demo/demo_screenshot.test)
set(_demo_results "${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}")
catkin_run_tests_target("rostest" "test_demo_demo_screenshot.test"
  "rostest-test_demo_demo_screenshot.xml"
  COMMAND "xvfb-run -a -s \"-screen 0 1280x800x24\" ${PYTHON_EXECUTABLE} /usr/bin/rostest --pkgdir=${PROJECT_SOURCE_DIR} --package=${PROJECT_NAME} --results-filename test_demo_demo_screenshot.xml --results-base-dir \"${CATKIN_TEST_RESULTS_DIR}\" ${PROJECT_SOURCE_DIR}/${_demo_test} screenshot:=${_demo_results}/demo_screenshot.ppm"
  DEPENDENCIES test_demo_screenshot demo_driver ellipse_collision_node)

# Units of the demo and of the screenshot test; no ROS master, no display.
catkin_add_gtest(test_demo_units
  test/demo/test_demo_units.cpp
  test/demo/rviz_top_down_view.cpp
  test/demo/screen_image.cpp
  src/ros/demo_trajectory.cpp)
target_include_directories(test_demo_units PRIVATE src/ros ${X11_INCLUDE_DIR})
target_link_libraries(test_demo_units ellipse_collision_core ${X11_LIBRARIES} gtest_main)
target_compile_options(test_demo_units PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
target_compile_definitions(test_demo_units PRIVATE
  DEMO_RVIZ_CONFIG="${PROJECT_SOURCE_DIR}/rviz/demo.rviz")
