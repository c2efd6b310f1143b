# The mc1 family's protocol and device tests (paths relative to tests/).
cambench_add_test(tst_mc1_protocol SOURCES comm/mc1/tst_mc1_protocol.cpp LIBS cambench_comm)
cambench_add_test(tst_mc1_link SOURCES comm/mc1/tst_mc1_link.cpp LIBS cambench_sim)
cambench_add_test(tst_mc1_device SOURCES comm/mc1/tst_mc1_device.cpp comm/mc1/mc1_test_bench.h LIBS cambench_sim)
cambench_add_test(tst_mc1_motion SOURCES comm/mc1/tst_mc1_motion.cpp comm/mc1/mc1_test_bench.h LIBS cambench_sim)
cambench_add_test(tst_mc1_stop_generation SOURCES comm/mc1/tst_mc1_stop_generation.cpp comm/worker/stop_at_request.h LIBS cambench_sim cambench_usecases)
cambench_add_test(tst_sim_mc1_controller SOURCES comm/mc1/tst_sim_mc1_controller.cpp LIBS cambench_sim)
include(${CMAKE_CURRENT_LIST_DIR}/../../fuzz/mc1_decoder.cmake)
