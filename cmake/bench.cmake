# Benchmarks (bench/), off in the normal build (-DELLIPSE_COLLISION_BENCHMARKS=ON).
# scripts/benchmark.sh builds and runs every one of them and prints the tables; CI runs
# `scripts/benchmark.sh --smoke` so that none rots. Peers come from Debian: Google Benchmark and
# FCL 0.7 (libfcl-dev, imported target `fcl`).
find_package(benchmark REQUIRED)
find_package(fcl REQUIRED)

# The scenes and pair mixes the programs draw from, and the oracles that judge the answers.
add_library(ellipse_collision_bench_scenes STATIC
  bench/bench_scenes.cpp
  test/support/contact_scale_oracle.cpp)
target_include_directories(ellipse_collision_bench_scenes PUBLIC
  ${PROJECT_SOURCE_DIR}/bench ${PROJECT_SOURCE_DIR}/test/support)
target_link_libraries(ellipse_collision_bench_scenes PUBLIC ellipse_collision_core quadmath)
target_compile_options(ellipse_collision_bench_scenes PRIVATE ${ELLIPSE_COLLISION_WARNINGS})

# function ellipse_collision_add_benchmark(NAME source... [LIBRARIES lib...])
function(ellipse_collision_add_benchmark name)
  cmake_parse_arguments(ARG "" "" "LIBRARIES" ${ARGN})
  add_executable(${name} ${ARG_UNPARSED_ARGUMENTS})
  target_link_libraries(${name} ellipse_collision_bench_scenes ${ARG_LIBRARIES}
    benchmark::benchmark)
  target_compile_options(${name} PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
endfunction()

# Pair tests beside FCL and the seed README's method, misclassifications against the oracle.
ellipse_collision_add_benchmark(bench_pair_tests bench/bench_pair_tests.cpp
  bench/reference_methods.cpp LIBRARIES fcl)
# src/core for overlap_detail.h: the polygonal cap study times overlap() with other caps.
target_include_directories(bench_pair_tests PRIVATE ${PROJECT_SOURCE_DIR}/src/core)

# Scene checks of 50 links against 100 to 100,000 obstacles.
ellipse_collision_add_benchmark(bench_scene_check bench/bench_scene_check.cpp)

# distance() beside FCL's distance query, accuracy against the quad rim oracle.
ellipse_collision_add_benchmark(bench_distance bench/bench_distance.cpp LIBRARIES fcl)

# First contact under translation beside the secant method it replaced, FCL's continuousCollide
# and sampling overlap() at 100 steps, misclassifications and time errors against the quad oracle.
ellipse_collision_add_benchmark(bench_first_contact bench/bench_first_contact.cpp
  bench/reference_methods.cpp test/support/first_contact_oracle.cpp
  test/support/grazing_passes.cpp LIBRARIES fcl)
# src/core for rotating_contact.h: the rotating mixes run the plain advancement beside the new
# steps and count both methods' distance() calls.
target_include_directories(bench_first_contact PRIVATE ${PROJECT_SOURCE_DIR}/src/core)

# The gate through ROS: command in to command out of the running node, beside a plain relay.
add_executable(bench_gate_roundtrip bench/bench_gate_roundtrip.cpp)
target_include_directories(bench_gate_roundtrip PRIVATE include bench ${catkin_INCLUDE_DIRS})
target_link_libraries(bench_gate_roundtrip ${catkin_LIBRARIES} Eigen3::Eigen)
target_compile_options(bench_gate_roundtrip PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(bench_gate_roundtrip ${PROJECT_NAME}_generate_messages_cpp)

# Service round trip: a ROS client of the running node, a plain main (not Google Benchmark);
# scripts/benchmark.sh starts a roscore and the node for it.
add_executable(bench_service_roundtrip bench/bench_service_roundtrip.cpp)
target_include_directories(bench_service_roundtrip PRIVATE include ${catkin_INCLUDE_DIRS})
target_link_libraries(bench_service_roundtrip ${catkin_LIBRARIES})
target_compile_options(bench_service_roundtrip PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
add_dependencies(bench_service_roundtrip ${PROJECT_NAME}_generate_messages_cpp)

# scan_obstacles' path for one 720-beam LaserScan: us per scan and % of one core at 40 Hz.
ellipse_collision_add_benchmark(bench_scan_obstacles bench/bench_scan_obstacles.cpp
  LIBRARIES ellipse_collision_ros)

# Continuous path checks at the size of issue 14: 10,000 poses x 1,000 obstacles x 20 links.
ellipse_collision_add_benchmark(bench_check_path bench/bench_check_path.cpp)

# One check of the application layer (placement through the cache, core check, answer), the
# node's own work per ~check_collisions call without ROS, beside the core check alone.
ellipse_collision_add_benchmark(bench_run_check bench/bench_run_check.cpp
  LIBRARIES ellipse_collision_app)

# The velocity gate for one command of a 20-link base among 1,000 to 100,000 obstacles.
ellipse_collision_add_benchmark(bench_velocity_gate bench/bench_velocity_gate.cpp)
# Command in to command out of the gate without ROS: app::CollisionMonitor::gateCommand().
ellipse_collision_add_benchmark(bench_gate_command bench/bench_gate_command.cpp
  LIBRARIES ellipse_collision_app)
