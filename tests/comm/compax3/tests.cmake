# The compax3 family's protocol and device tests (paths relative to tests/).
cambench_add_test(tst_compax3_drive SOURCES comm/compax3/tst_compax3_drive.cpp
  comm/engine/scripted_line.h comm/engine/scripted_line.cpp LIBS cambench_sim cambench_usecases)
cambench_add_test(tst_compax3_stop_generation SOURCES comm/compax3/tst_compax3_stop_generation.cpp comm/worker/stop_at_request.h LIBS cambench_sim)
include(${CMAKE_CURRENT_LIST_DIR}/../../fuzz/compax3_reply.cmake)
