# Python bindings of the ROS-free core (src/python/, doc/python.md): the module
# ellipse_collision.core, built by pybind11 next to the package's generated messages, so that
# `from ellipse_collision import core` works after `source devel/setup.bash` and in an installed
# workspace. Debian's pybind11-dev and /usr/bin/python3 (scripts/setup.sh).
# Python3_FOUND is already set here (by the configuration of a dependency), which makes pybind11
# use the functions of CMake's FindPython3 (python3_add_library): load them, for catkin's
# interpreter (/usr/bin/python3, scripts/build.sh).
set(Python3_EXECUTABLE ${PYTHON_EXECUTABLE})
find_package(Python3 REQUIRED COMPONENTS Interpreter Development.Module)
find_package(pybind11 CONFIG REQUIRED)

pybind11_add_module(ellipse_collision_python_core
  src/python/core_module.cpp
  src/python/value_types.cpp
  src/python/pair_functions.cpp
  src/python/ellipse_rows.cpp
  src/python/batch_functions.cpp
  src/python/ellipse_batch.cpp
  src/python/enclosing_functions.cpp
  src/python/scene_functions.cpp)
target_link_libraries(ellipse_collision_python_core PRIVATE ellipse_collision_core)
target_compile_options(ellipse_collision_python_core PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
set_target_properties(ellipse_collision_python_core PROPERTIES
  OUTPUT_NAME core
  LIBRARY_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_PYTHON_DESTINATION})

install(TARGETS ellipse_collision_python_core
  LIBRARY DESTINATION ${CATKIN_PACKAGE_PYTHON_DESTINATION})
