# Every test (test/). Included from CMakeLists.txt inside if(CATKIN_ENABLE_TESTING).
# test/support/ holds what several tests share: the quad-precision oracles, ellipse builders and
# random generators, the brute-force scene reference.
find_package(rostest REQUIRED)
find_package(std_srvs REQUIRED)
find_package(X11 REQUIRED)
set(_support ${PROJECT_SOURCE_DIR}/test/support)

# ellipse_collision_add_gtest(NAME LIBRARIES libs... SOURCES sources...): a gtest that needs no
# ROS master, with gtest_main and the test support headers.
function(ellipse_collision_add_gtest name)
  cmake_parse_arguments(ARG "" "" "LIBRARIES;SOURCES" ${ARGN})
  catkin_add_gtest(${name} ${ARG_SOURCES})
  target_include_directories(${name} PRIVATE ${_support})
  target_link_libraries(${name} ${ARG_LIBRARIES} gtest_main)
  target_compile_options(${name} PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
endfunction()

# ---- core (test/core): link the core alone, so a stray ROS dependency fails the build ----------
ellipse_collision_add_gtest(test_core LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_ellipse.cpp
  test/core/test_contact_scale.cpp
  test/core/test_contact_scale_quartic.cpp
  test/core/test_polygonal_early_out.cpp
  test/core/test_overlap_accuracy.cpp
  test/core/test_early_outs.cpp
  test/core/test_batch_overlap.cpp
  test/core/test_pair_line_parser.cpp
  test/core/test_motion_line_parser.cpp
  test/core/test_unique_names.cpp
  test/core/test_number_format.cpp
  test/core/test_number_fields.cpp
  test/core/test_gate_action.cpp
  test/core/test_free_space.cpp
  test/core/test_path_motion.cpp
  test/core/test_overlap.cpp
  test/core/test_relative_shape.cpp
  test/core/test_rotating_pair.cpp
  test/core/test_rotating_separation.cpp
  test/core/test_rotating_step_bounds.cpp
  test/core/test_enclosing_ellipsoid.cpp
  test/core/test_ellipse_polygon.cpp
  test/core/test_scan_contours.cpp
  test/support/contact_scale_oracle.cpp)
# The early-out stages are internal to overlap(): their test reads src/core's detail headers.
target_include_directories(test_core PRIVATE ${PROJECT_SOURCE_DIR}/src/core)
ellipse_collision_add_gtest(test_scene_core LIBRARIES ellipse_collision_core SOURCES
  test/core/test_frame_projection.cpp
  test/core/test_scene_check.cpp
  test/core/test_scene_broadphase.cpp
  test/core/test_scene_clearance.cpp
  test/core/test_median_partition.cpp
  test/core/test_scene.cpp
  test/core/test_scene_entry_ref.cpp
  test/core/test_scene_nearest.cpp
  test/core/test_indexed_obstacles.cpp
  test/core/test_pair_culling.cpp
  test/core/test_pair_collector.cpp)
# src/core for scene_check_detail.h: the scene tests force each culling kernel of the narrow phase.
target_include_directories(test_scene_core PRIVATE ${PROJECT_SOURCE_DIR}/src/core)
ellipse_collision_add_gtest(test_distance LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_distance.cpp
  test/support/contact_scale_oracle.cpp)
ellipse_collision_add_gtest(test_performance_core LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_prepared_ellipse.cpp
  test/core/test_broadphase.cpp
  test/support/contact_scale_oracle.cpp)

# First time of contact of moving ellipses against the quad-precision oracle.
ellipse_collision_add_gtest(test_first_contact LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_first_contact.cpp
  test/support/first_contact_oracle.cpp
  test/support/grazing_passes.cpp)
# src/core for rotating_contact.h: the grazing tests count the rotating path's work.
target_include_directories(test_first_contact PRIVATE ${PROJECT_SOURCE_DIR}/src/core)

# The rotating pairs' first contact on its own: never late and within its resolution against
# long double poses, the quad contact scale sampled densely and bisected.
ellipse_collision_add_gtest(test_rotating_contact LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_rotating_contact.cpp
  test/support/contact_scale_oracle.cpp)
# src/core for rotating_contact.h, an internal header.
target_include_directories(test_rotating_contact PRIVATE ${PROJECT_SOURCE_DIR}/src/core)

# Continuous path checks against the quad oracle and brute force over every pair.
ellipse_collision_add_gtest(test_path_check LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_path_check.cpp
  test/core/test_contact_prediction.cpp
  test/support/first_contact_oracle.cpp
  test/support/grazing_passes.cpp)
# src/core for rotating_contact.h: the grazing test counts the rotating path's work.
target_include_directories(test_path_check PRIVATE ${PROJECT_SOURCE_DIR}/src/core)

# Motion under a twist: poses and first contacts against quad-precision arcs, the translation
# oracle and dense overlap() scans.
ellipse_collision_add_gtest(test_twist_motion LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_twist_motion.cpp
  test/support/twist_oracle.cpp
  test/support/first_contact_oracle.cpp
  test/support/grazing_passes.cpp)
# src/core for rotating_contact.h: the grazing test counts the rotating path's work.
target_include_directories(test_twist_motion PRIVATE ${PROJECT_SOURCE_DIR}/src/core)

# The braking model: the scale profile against its integral, brakingContact() never late against
# a dense scan of the exact motion.
ellipse_collision_add_gtest(test_base_braking LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_base_braking.cpp
  test/support/twist_oracle.cpp)

# The velocity gate: its decisions against dense overlap() scans of the exact arcs, and driving a
# simulated base that answers late and brakes at bounded rates (core::SimulatedBase).
ellipse_collision_add_gtest(test_velocity_gate LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_velocity_gate.cpp
  test/support/twist_oracle.cpp
  test/support/first_contact_oracle.cpp
  test/support/grazing_passes.cpp)
target_include_directories(test_velocity_gate PRIVATE ${PROJECT_SOURCE_DIR}/src/core)

# Ellipsoids: the shadow against projected surface samples and the link ellipsoids of URDF shapes
# in quad precision (the minimum-volume fit is in test_core: test_enclosing_ellipsoid.cpp).
ellipse_collision_add_gtest(test_ellipsoid LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_ellipsoid.cpp
  test/core/test_shape_hull.cpp)

# Minimum-area enclosing ellipses (link fitting, sensor clusters) against their own oracle.
ellipse_collision_add_gtest(test_enclosing_ellipse LIBRARIES ellipse_collision_core quadmath SOURCES
  test/core/test_enclosing_ellipse.cpp
  test/core/test_shape_outline.cpp
  test/core/test_point_clusters.cpp
  test/support/enclosing_ellipse_oracle.cpp)

catkin_add_gtest(test_check_ellipses test/core/test_check_ellipses.cpp)
target_compile_definitions(test_check_ellipses PRIVATE
  CHECK_ELLIPSES_BIN="$<TARGET_FILE:check_ellipses>")
add_dependencies(test_check_ellipses check_ellipses)
target_compile_options(test_check_ellipses PRIVATE ${ELLIPSE_COLLISION_WARNINGS})

# ---- application layer (test/app): no ROS library, transforms from a table --------------------
ellipse_collision_add_gtest(test_app LIBRARIES ellipse_collision_app quadmath SOURCES
  test/app/test_ellipse_registry.cpp
  test/app/test_ellipse_spec.cpp
  test/app/test_field_error.cpp
  test/app/test_gate_config.cpp
  test/app/test_incident_recorder.cpp
  test/app/test_incident_replay.cpp
  test/app/test_velocity_command.cpp
  test/app/test_transform_lookup.cpp
  test/app/test_placement_cache.cpp
  test/app/test_tunable_settings.cpp
  test/app/test_scan_name_keeper.cpp
  test/app/test_scan_cut_memory.cpp
  test/app/test_obstacle_persistence.cpp
  test/app/test_frame_placer.cpp
  test/app/test_standing_obstacles.cpp
  test/app/test_sensor_obstacle_series.cpp
  test/app/test_stored_placement.cpp
  test/app/test_collision_check.cpp
  test/app/test_collision_monitor.cpp
  test/app/test_velocity_gate.cpp
  test/app/test_gate_marker_layout.cpp
  test/app/test_obstacle_source.cpp
  test/app/test_source_freshness.cpp
  test/app/test_contact_prediction.cpp
  test/app/test_obstacle_store.cpp
  test/app/test_obstacle_store_writer.cpp
  test/app/test_check_health.cpp
  test/app/test_joint_chain.cpp
  test/app/test_link_fitting.cpp
  test/app/test_marker_layout.cpp
  test/app/test_path_request.cpp
  test/app/test_range_obstacle.cpp
  test/app/test_ellipsoid_links.cpp
  test/app/test_ellipsoid_obstacles.cpp
  test/app/test_obstacle_tracker.cpp
  test/app/test_fleet_footprint.cpp
  test/app/test_fleet_roster.cpp
  test/app/test_tracked_crossings.cpp)

# scan_obstacles' guarantees on ray-cast scenes: coverage, free space, doorways, names, counts.
ellipse_collision_add_gtest(test_scan_contours LIBRARIES ellipse_collision_app SOURCES
  test/app/test_scan_contours.cpp)

# ---- ROS layer units (test/ros): conversions, parameters, markers; no master -------------------
ellipse_collision_add_gtest(test_ros_units LIBRARIES ellipse_collision_ros SOURCES
  test/ros/test_conversions.cpp
  test/ros/test_node_config.cpp
  test/ros/test_param_reading.cpp
  test/ros/test_ellipse_params.cpp
  test/ros/test_gate_params.cpp
  test/ros/test_fleet_params.cpp
  test/ros/test_incident_params.cpp
  test/ros/test_source_params.cpp
  test/ros/test_scan_params.cpp
  test/ros/test_collision_markers.cpp
  test/ros/test_scan_obstacles_units.cpp
  test/ros/test_gate_markers.cpp
  test/ros/test_tf_lookup.cpp)

# URDF links to ellipses (test/fixtures/), fit_link_ellipses' YAML read back by the node's parser.
ellipse_collision_add_gtest(test_urdf_links LIBRARIES ellipse_collision_ros SOURCES
  test/ros/test_urdf_links.cpp)
target_compile_definitions(test_urdf_links PRIVATE
  ELLIPSE_COLLISION_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
  FIT_LINK_ELLIPSES_BIN="$<TARGET_FILE:fit_link_ellipses>")
add_dependencies(test_urdf_links fit_link_ellipses)

# ---- rostests: roscore, the real node, a tf helper and a gtest client --------------------------
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
  target_include_directories(${target} PRIVATE ${_support})
  target_compile_definitions(${target} PRIVATE
    ELLIPSE_COLLISION_NODE_BIN="$<TARGET_FILE:ellipse_collision_node>")
  add_dependencies(${target} ellipse_collision_node tf_test_broadcaster
    ${PROJECT_NAME}_generate_messages)
endfunction()

ellipse_collision_add_rostest(test_node_services test/ros/node_services.test
  test/ros/test_node_services.cpp)
ellipse_collision_add_rostest(test_node_topics test/ros/node_topics.test
  test/ros/test_node_topics.cpp)
# When ~collisions is published: at `rate`, and on a full call only when the state changed.
# The velocity gate on simulated time: a robot the client integrates from ~cmd_vel_out.
ellipse_collision_add_rostest(test_gate test/ros/gate.test test/ros/test_gate.cpp)
target_include_directories(test_gate PRIVATE ${std_srvs_INCLUDE_DIRS})
# The braking rule on simulated time: a base that answers late and brakes at bounded rates.
ellipse_collision_add_rostest(test_gate_braking test/ros/gate_braking.test
  test/ros/test_gate_braking.cpp)
target_include_directories(test_gate_braking PRIVATE ${std_srvs_INCLUDE_DIRS}
  ${PROJECT_SOURCE_DIR}/test/support)
ellipse_collision_add_rostest(test_state_publishing test/ros/state_publishing.test
  test/ros/test_state_publishing.cpp)
ellipse_collision_add_rostest(test_stale_data test/ros/stale_data.test
  test/ros/test_stale_data.cpp)
# Several obstacle sources: two scanners in one node, one falls silent.
ellipse_collision_add_rostest(test_sources test/ros/sources.test test/ros/test_sources.cpp)
# Robots that see each other: four nodes in their own namespaces, four braking bases.
ellipse_collision_add_rostest(test_fleet test/ros/fleet.test test/ros/test_fleet.cpp)

# A person crossing ahead, through the gate of two nodes, with and without tracking (issue 42).
ellipse_collision_add_rostest(test_crossings test/ros/crossings.test test/ros/test_crossings.cpp)
ellipse_collision_add_rostest(test_time_jump test/ros/time_jump.test
  test/ros/test_time_jump.cpp)
ellipse_collision_add_rostest(test_respawn test/ros/respawn.test
  test/ros/test_respawn.cpp)
ellipse_collision_add_rostest(test_node_cli test/ros/node_cli.test
  test/ros/test_node_cli.cpp)
add_dependencies(test_node_cli fit_link_ellipses)
# Issue 34: the package's launch file with links_from_urdf; its guard fits the URDF too.
ellipse_collision_add_rostest(test_urdf_launch test/ros/urdf_launch.test
  test/ros/test_urdf_launch.cpp)
# Issue 34: an arm's links fitted as ellipsoids; their footprints over a roll and pitch sweep.
ellipse_collision_add_rostest(test_arm_links test/ros/arm_links.test test/ros/test_arm_links.cpp)
ellipse_collision_add_rostest(test_bad_config test/ros/bad_config.test
  test/ros/test_bad_config.cpp)
# A synthetic LaserScan through scan_obstacles into the node's ~obstacles.
ellipse_collision_add_rostest(test_scan_obstacles test/ros/scan_obstacles.test
  test/ros/test_scan_obstacles.cpp)
add_dependencies(test_scan_obstacles scan_obstacles)
# The same client against launch/scan_pipeline_nodelets.launch: both nodes as nodelets in one
# manager, and what the manager shows and refuses.
ellipse_collision_add_rostest(test_scan_pipeline_nodelets test/ros/scan_pipeline_nodelets.test
  test/ros/test_scan_obstacles.cpp test/ros/test_scan_pipeline_nodelets.cpp)
add_dependencies(test_scan_pipeline_nodelets ellipse_collision_nodelets)

# Issue 14: ~check_path and time to contact through the real node, against the quad oracle.
ellipse_collision_add_rostest(test_motion test/ros/motion.test
  test/ros/test_motion.cpp test/support/first_contact_oracle.cpp)
target_link_libraries(test_motion quadmath)

# The rospy example client against the example configuration (a Python rostest).
add_rostest(test/ros/python_client.test
  DEPENDENCIES ellipse_collision_node ${PROJECT_NAME}_generate_messages)

# dynamic_reconfigure through the real node, with Debian's dynamic_reconfigure client (Python).
add_rostest(test/ros/reconfigure.test
  DEPENDENCIES ellipse_collision_node ${PROJECT_NAME}_generate_messages ${PROJECT_NAME}_gencfg)

# Every message and service type a user meets loads in Debian's Python (rosservice, rostopic,
# rospy): catches a missing python3-*-msgs package in scripts/setup.sh.
catkin_run_tests_target("python" "message_types" "python-message_types.xml"
  COMMAND "${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/python/check_message_types.py ${PROJECT_SOURCE_DIR} --junit ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/python-message_types.xml"
  DEPENDENCIES ${PROJECT_NAME}_generate_messages)

# The Python bindings (ellipse_collision.core) against check_ellipses, closed forms and the
# 40-digit contact scale oracle (test/support/contact_scale_oracle.py); run in the workspace's
# environment, so `from ellipse_collision import core` finds the module in devel/.
catkin_run_tests_target("python" "core_bindings" "python-core_bindings.xml"
  COMMAND "${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/python/test_core_bindings.py ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/check_ellipses --gtest_output=xml:${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/python-core_bindings.xml"
  DEPENDENCIES ellipse_collision_python_core check_ellipses)

# incident_report (scripts/incident_report) on bags written in the node's format: the page, the
# scene figure's pixels, a plain ~gate_state recording.
catkin_run_tests_target("python" "incident_report" "python-incident_report.xml"
  COMMAND "${PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/test/python/test_incident_report.py --gtest_output=xml:${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/python-incident_report.xml"
  DEPENDENCIES ${PROJECT_NAME}_generate_messages)

# ---- reliability (test/reliability): hostile requests to every service and the ~obstacles topic,
# bad configuration files started through the launch file, the load test ----------------------
ellipse_collision_add_rostest(test_hostile_requests test/reliability/hostile_requests.test
  test/reliability/test_hostile_requests.cpp)
ellipse_collision_add_rostest(test_bad_startup test/reliability/bad_startup.test
  test/reliability/test_bad_startup.cpp)
target_compile_definitions(test_bad_startup PRIVATE
  ELLIPSE_COLLISION_SOURCE_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
# 60 s of load by default; a quick run: rostest $PWD/test/reliability/load.test duration:=10
ellipse_collision_add_rostest(test_load test/reliability/load.test
  test/reliability/test_load.cpp)
ellipse_collision_add_rostest(test_storm test/reliability/storm.test
  test/reliability/test_storm.cpp)

# ---- demo (test/demo): the whole demo with rviz in a virtual X server, judged from a screenshot
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
ellipse_collision_add_gtest(test_demo_units LIBRARIES ellipse_collision_core ${X11_LIBRARIES}
  SOURCES
  test/demo/test_demo_units.cpp
  test/demo/rviz_top_down_view.cpp
  test/demo/screen_image.cpp
  demo/src/demo_scanner.cpp
  demo/src/demo_world.cpp
  demo/src/demo_base_control.cpp
  demo/src/demo_arm_guard.cpp
  demo/src/demo_log_on_change.cpp
  demo/src/demo_trajectory.cpp)
target_include_directories(test_demo_units PRIVATE demo/src ${X11_INCLUDE_DIR})
target_compile_definitions(test_demo_units PRIVATE
  DEMO_RVIZ_CONFIG="${PROJECT_SOURCE_DIR}/demo/rviz/demo.rviz")

# ---- the documented commands (test/docs, doc/testing.md) ----------------------------------------
# doc_static needs no node; the pages' tests start what the page starts (roslaunch, rviz) on the
# rostest's master. README's tour opens rviz, so its test runs under xvfb-run like the demo's.
add_rostest(test/docs/doc_static.test)
add_rostest(test/docs/doc_node_reference.test
  DEPENDENCIES ellipse_collision_node ${PROJECT_NAME}_generate_messages)
add_rostest(test/docs/doc_tools.test DEPENDENCIES check_ellipses fit_link_ellipses)
add_rostest(test/docs/doc_python.test DEPENDENCIES ellipse_collision_python_core)
set(_readme_test test/docs/doc_readme.test)
catkin_run_tests_target("rostest" "test_docs_doc_readme.test" "rostest-test_docs_doc_readme.xml"
  COMMAND "xvfb-run -a -s \"-screen 0 1280x800x24\" ${PYTHON_EXECUTABLE} /usr/bin/rostest --pkgdir=${PROJECT_SOURCE_DIR} --package=${PROJECT_NAME} --results-filename test_docs_doc_readme.xml --results-base-dir \"${CATKIN_TEST_RESULTS_DIR}\" ${PROJECT_SOURCE_DIR}/${_readme_test}"
  DEPENDENCIES ellipse_collision_node ${PROJECT_NAME}_generate_messages)

# The simulated base the gate's tests and the demo drive: its rest against the closed forms.
ellipse_collision_add_gtest(test_simulated_base LIBRARIES ellipse_collision_core SOURCES
  test/core/test_simulated_base.cpp)
# The incident recorder through the real node: a STOP to a bag, ~save_incident, max_files, and a
# directory that cannot be created.
ellipse_collision_add_rostest(test_incidents test/ros/incidents.test test/ros/test_incidents.cpp)
target_include_directories(test_incidents PRIVATE ${std_srvs_INCLUDE_DIRS})
