# ROS-free core (include/ellipse_collision/core/, src/core/): Eigen and the standard library only.
# The command-line tool check_ellipses is a user of the core alone.
add_library(ellipse_collision_core ${ELLIPSE_COLLISION_CORE_SOURCES})
target_include_directories(ellipse_collision_core PUBLIC include)
target_link_libraries(ellipse_collision_core PUBLIC Eigen3::Eigen)
target_compile_options(ellipse_collision_core PRIVATE ${ELLIPSE_COLLISION_WARNINGS}
  ${ELLIPSE_COLLISION_LIBRARY_OPTIONS})
target_link_options(ellipse_collision_core PRIVATE ${ELLIPSE_COLLISION_LIBRARY_LINK_OPTIONS})

add_executable(check_ellipses src/tools/check_ellipses.cpp)
target_link_libraries(check_ellipses ellipse_collision_core)
target_compile_options(check_ellipses PRIVATE ${ELLIPSE_COLLISION_WARNINGS})

install(TARGETS ellipse_collision_core check_ellipses
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
