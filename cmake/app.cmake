# ROS-free application layer (include/ellipse_collision/app/, src/app/): stored ellipses, request
# validation, the orchestration of a check. Transforms reach it through app::TransformLookup, so it
# is tested and fuzzed without a master; no ROS header, no ROS library on its link line.
# The obstacle store's writer runs on a thread of its own (app/obstacle_store_writer.h).
find_package(Threads REQUIRED)
add_library(ellipse_collision_app ${ELLIPSE_COLLISION_APP_SOURCES})
target_include_directories(ellipse_collision_app PUBLIC include)
target_link_libraries(ellipse_collision_app PUBLIC ellipse_collision_core Threads::Threads)
target_compile_options(ellipse_collision_app PRIVATE ${ELLIPSE_COLLISION_WARNINGS}
  ${ELLIPSE_COLLISION_LIBRARY_OPTIONS})
target_link_options(ellipse_collision_app PRIVATE ${ELLIPSE_COLLISION_LIBRARY_LINK_OPTIONS})

install(TARGETS ellipse_collision_app
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
