# Collision benchmarks (Google Benchmark): pair tests beside FCL 0.7 and the seed README's method,
# with misclassifications counted against the quad-precision oracle of the accuracy tests, and
# scene checks of 50 links against up to 100,000 obstacles. scripts/benchmark.sh builds and runs
# them and prints one table.
find_package(benchmark REQUIRED)
find_package(fcl REQUIRED)  # Debian's libfcl-dev (FCL 0.7): imported target `fcl`

# The scenes and pair mixes both programs draw from, and the oracle that judges the pairs.
add_library(ellipse_collision_bench_scenes STATIC
  bench/bench_scenes.cpp
  test/core/contact_scale_oracle.cpp)
target_include_directories(ellipse_collision_bench_scenes PUBLIC
  ${PROJECT_SOURCE_DIR}/bench ${PROJECT_SOURCE_DIR}/test/core)
target_link_libraries(ellipse_collision_bench_scenes PUBLIC ellipse_collision_core quadmath)
target_compile_options(ellipse_collision_bench_scenes PRIVATE ${ELLIPSE_COLLISION_WARNINGS})

add_executable(bench_pair_tests bench/bench_pair_tests.cpp bench/reference_methods.cpp)
# src/core for overlap_detail.h: the polygonal cap study times overlap() with other caps.
target_include_directories(bench_pair_tests PRIVATE ${PROJECT_SOURCE_DIR}/src/core)
target_link_libraries(bench_pair_tests ellipse_collision_bench_scenes fcl benchmark::benchmark)
target_compile_options(bench_pair_tests PRIVATE ${ELLIPSE_COLLISION_WARNINGS})

add_executable(bench_scene_check bench/bench_scene_check.cpp)
target_link_libraries(bench_scene_check ellipse_collision_bench_scenes benchmark::benchmark)
target_compile_options(bench_scene_check PRIVATE ${ELLIPSE_COLLISION_WARNINGS})

# Service round trip (issue 7): a ROS client of the running node, a plain main (not Google
# Benchmark); scripts/benchmark.sh starts a roscore and the node for it.
add_executable(bench_service_roundtrip bench/bench_service_roundtrip.cpp)
target_include_directories(bench_service_roundtrip PRIVATE include ${catkin_INCLUDE_DIRS})
target_link_libraries(bench_service_roundtrip ${catkin_LIBRARIES})
target_compile_options(bench_service_roundtrip PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(bench_service_roundtrip ${PROJECT_NAME}_generate_messages_cpp)
