# Google Benchmark programs.

# ---- bench_distance (issue 6): distance() beside FCL's distance query --------------------------
# ns per pair and accuracy against the quad oracle shared with test_distance (distance_oracle.h).
find_package(benchmark REQUIRED)
find_package(fcl REQUIRED)  # Debian's libfcl-dev (FCL 0.7): imported target `fcl`
add_executable(bench_distance bench/bench_distance.cpp)
target_include_directories(bench_distance PRIVATE ${PROJECT_SOURCE_DIR}/test/core)
target_link_libraries(bench_distance ellipse_collision_core fcl benchmark::benchmark quadmath)
target_compile_options(bench_distance PRIVATE ${ELLIPSE_COLLISION_WARNINGS})
# ---- end bench_distance ------------------------------------------------------------------------
