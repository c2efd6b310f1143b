# The request engine with a fake framing on a virtual clock, and the CamCon
# ASCII backend on its own (paths relative to tests/).
cambench_add_test(tst_engine_request_engine
  SOURCES comm/engine/tst_request_engine.cpp comm/engine/scripted_line.h
          comm/engine/scripted_line.cpp
  LIBS cambench_comm)
cambench_add_test(tst_engine_ascii_backend SOURCES comm/engine/tst_ascii_backend.cpp LIBS cambench_comm)
cambench_add_test(tst_engine_line_timeouts
  SOURCES comm/engine/tst_line_timeouts.cpp comm/engine/scripted_line.h
          comm/engine/scripted_line.cpp
  LIBS cambench_comm)
