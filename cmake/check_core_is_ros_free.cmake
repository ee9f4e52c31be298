# Fails the configure step when a source or public header of the core or of the application layer
# includes a ROS header (include/ellipse_collision/{core,app}/, src/{core,app}/).
file(GLOB_RECURSE _ros_free_files
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/* ${CMAKE_CURRENT_SOURCE_DIR}/src/app/*
  ${CMAKE_CURRENT_SOURCE_DIR}/include/ellipse_collision/core/*
  ${CMAKE_CURRENT_SOURCE_DIR}/include/ellipse_collision/app/*)
foreach(_file ${_ros_free_files})
  file(STRINGS ${_file} _ros_includes
    REGEX "#include *[<\"](ros|tf2|tf2_ros|tf2_eigen|std_msgs|geometry_msgs|visualization_msgs|diagnostic_msgs|sensor_msgs|nav_msgs|xmlrpcpp|urdf|urdf_model|urdf_parser|resource_retriever|assimp|ellipse_collision/ros)/")
  if(_ros_includes)
    message(FATAL_ERROR "ROS header in the ROS-free core or application layer: ${_file}: ${_ros_includes}")
  endif()
endforeach()
