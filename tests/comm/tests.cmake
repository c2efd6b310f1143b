cambench_add_test(tst_link_serial_transport SOURCES comm/link/tst_serial_transport.cpp comm/link/pty_device.h comm/link/pty_device.cpp LIBS cambench_sim)
cambench_add_test(tst_link_tcp_transport SOURCES comm/link/tst_tcp_transport.cpp comm/link/pty_device.h comm/link/pty_device.cpp LIBS cambench_sim)
cambench_add_test(tst_link_transport_factory SOURCES comm/link/tst_transport_factory.cpp LIBS cambench_sim)
cambench_add_test(tst_link_traffic SOURCES comm/link/tst_traffic.cpp LIBS cambench_sim)
cambench_add_test(tst_sim_executable SOURCES comm/sim/tst_sim_executable.cpp LIBS cambench_comm cambench_child_process Qt6::SerialPort Qt6::Network)
target_compile_definitions(tst_sim_executable PRIVATE CAMBENCH_SIM_EXECUTABLE="$<TARGET_FILE:cambench-sim>")
add_dependencies(tst_sim_executable cambench-sim)
cambench_add_test(tst_worker_job_queue SOURCES comm/worker/tst_job_queue.cpp LIBS cambench_sim)
cambench_add_test(tst_worker_comm_worker SOURCES comm/worker/tst_comm_worker.cpp comm/link/pty_device.h comm/link/pty_device.cpp LIBS cambench_sim)
# Issue 30: the simulated machine's shaft, its port keys, two in-process ports on one.
cambench_add_test(tst_sim_shaft SOURCES comm/sim/tst_sim_shaft.cpp LIBS cambench_sim)
target_compile_definitions(tst_sim_shaft PRIVATE
  CAMBENCH_DEMO_MACHINE="${PROJECT_SOURCE_DIR}/docs/demo-machine.json")
# Each family's protocol and device tests, listed in its folder.
cambench_include_family_lists(${CMAKE_CURRENT_LIST_DIR} tests.cmake)
