# Fails the configure step when a core source or public core header includes a ROS header.
# Public core headers are in include/ellipse_collision/core/.
file(GLOB_RECURSE _core_sources ${CMAKE_CURRENT_SOURCE_DIR}/src/core/*)
file(GLOB _core_headers ${CMAKE_CURRENT_SOURCE_DIR}/include/ellipse_collision/core/*.h)
set(_core_files ${_core_sources} ${_core_headers})
foreach(_file ${_core_files})
  file(STRINGS ${_file} _ros_includes
    REGEX "#include *[<\"](ros|tf2|tf2_ros|tf2_eigen|std_msgs|geometry_msgs|visualization_msgs|diagnostic_msgs|xmlrpcpp|ellipse_collision/ros)/")
  if(_ros_includes)
    message(FATAL_ERROR "ROS header in the ROS-free core: ${_file}: ${_ros_includes}")
  endif()
endforeach()
