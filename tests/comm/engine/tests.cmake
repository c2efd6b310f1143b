# The request engine with a fake framing on a virtual clock (paths relative
# to tests/; the CamCon ASCII backend's tests are in comm/camcon/ascii/).
cambench_add_test(tst_engine_request_engine
  SOURCES comm/engine/tst_request_engine.cpp comm/engine/scripted_line.h
          comm/engine/scripted_line.cpp
  LIBS cambench_comm)
