# The one list of the ROS-free sources, relative to the package root. The catkin build
# (cmake/core.cmake, cmake/app.cmake) and the standalone fuzz build (fuzz/CMakeLists.txt via
# cmake/fuzz.cmake) both compile exactly these.
set(ELLIPSE_COLLISION_CORE_SOURCES
  src/core/broadphase.cpp
  src/core/contact_prediction.cpp
  src/core/contact_scale_quartic.cpp
  src/core/distance.cpp
  src/core/ellipse_polygon.cpp
  src/core/eigenvalue_test.cpp
  src/core/ellipse.cpp
  src/core/enclosing_ellipse.cpp
  src/core/first_contact.cpp
  src/core/frame_projection.cpp
  src/core/indexed_obstacles.cpp
  src/core/median_partition.cpp
  src/core/motion_line_parser.cpp
  src/core/number_fields.cpp
  src/core/number_format.cpp
  src/core/overlap.cpp
  src/core/pair_line_parser.cpp
  src/core/path_check.cpp
  src/core/path_motion.cpp
  src/core/point_clusters.cpp
  src/core/polygonal_test.cpp
  src/core/prepared_ellipse.cpp
  src/core/relative_shape.cpp
  src/core/scene.cpp
  src/core/scene_check.cpp
  src/core/shape_outline.cpp
  src/core/unique_names.cpp)

set(ELLIPSE_COLLISION_APP_SOURCES
  src/app/check_health.cpp
  src/app/collision_check.cpp
  src/app/contact_prediction.cpp
  src/app/ellipse_registry.cpp
  src/app/ellipse_spec.cpp
  src/app/field_error.cpp
  src/app/link_fitting.cpp
  src/app/obstacle_store.cpp
  src/app/obstacle_store_writer.cpp
  src/app/path_request.cpp
  src/app/scan_obstacles.cpp
  src/app/scene_placement.cpp
  src/app/placement_cache.cpp
  src/app/standing_obstacles.cpp
  src/app/transform_lookup.cpp)
