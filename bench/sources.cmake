# Benchmark: prints figures against the throttled simulator (not a test).
add_executable(cambench-bench cambench_bench.cpp protocol_bench.h protocol_bench.cpp
  bench_run.h bench_run.cpp mc1_bench.h mc1_bench.cpp mc1_live_stop_bench.h mc1_live_stop_bench.cpp compax3_bench.h compax3_bench.cpp cambus_bench.h cambus_bench.cpp
  machine_bench.h machine_bench.cpp bench_process.h bench_process.cpp)
target_link_libraries(cambench-bench PRIVATE cambench_registry cambench_comm cambench_sim
  cambench_usecases cambench_child_process)
# The machine benchmark runs the real executables.
target_compile_definitions(cambench-bench PRIVATE
  CAMBENCH_SIM_EXE="$<TARGET_FILE:cambench-sim>"
  CAMBENCH_CLI_EXE="$<TARGET_FILE:cambench-cli>")
add_dependencies(cambench-bench cambench-sim cambench-cli)
