# The camcon family's protocol, simulator and device tests (paths relative
# to tests/): its ASCII framing, the table interface (table/), the Cam-BUS.
cambench_add_test(tst_protocol_frame SOURCES comm/camcon/ascii/tst_frame.cpp LIBS cambench_sim)
cambench_add_test(tst_protocol_stream_decoder SOURCES comm/camcon/ascii/tst_stream_decoder.cpp LIBS cambench_sim)
cambench_add_test(tst_protocol_catalogue SOURCES comm/camcon/ascii/tst_catalogue.cpp LIBS cambench_sim)
cambench_add_test(tst_protocol_command_codec SOURCES comm/camcon/ascii/tst_command_codec.cpp LIBS cambench_sim)
cambench_add_test(tst_link_ascii_link SOURCES comm/camcon/ascii/tst_ascii_link.cpp comm/link/pty_device.h comm/link/pty_device.cpp LIBS cambench_sim)
cambench_add_test(tst_sim_device SOURCES comm/camcon/sim/tst_sim_device.cpp comm/camcon/sim/sim_test_client.h comm/camcon/sim/sim_test_client.cpp LIBS cambench_sim)
cambench_add_test(tst_sim_line SOURCES comm/camcon/sim/tst_sim_line.cpp comm/camcon/sim/sim_test_client.h comm/camcon/sim/sim_test_client.cpp LIBS cambench_sim)
cambench_add_test(tst_sim_table_line SOURCES comm/camcon/sim/tst_sim_table_line.cpp LIBS cambench_sim)
cambench_add_test(tst_cambus_block SOURCES comm/camcon/cambus/tst_cambus_block.cpp LIBS cambench_comm)
cambench_add_test(tst_cambus_bus SOURCES comm/camcon/cambus/tst_cambus_bus.cpp LIBS cambench_sim)
cambench_add_test(tst_cambus_camcon SOURCES comm/camcon/cambus/tst_cambus_camcon.cpp LIBS cambench_sim)
include(${CMAKE_CURRENT_LIST_DIR}/../../fuzz/cambus_station.cmake)
cambench_add_test(tst_engine_ascii_backend SOURCES comm/camcon/ascii/tst_ascii_backend.cpp LIBS cambench_comm)
cambench_add_test(tst_engine_line_timeouts
  SOURCES comm/camcon/ascii/tst_line_timeouts.cpp comm/engine/scripted_line.h
          comm/engine/scripted_line.cpp
  LIBS cambench_comm)
include(${CMAKE_CURRENT_LIST_DIR}/table/tests.cmake)
