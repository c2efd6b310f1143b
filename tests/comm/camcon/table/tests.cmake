# The byte level of the table interface (comm/camcon/table) and its fuzzer.
cambench_add_test(tst_table_link_3964r SOURCES comm/camcon/table/tst_link_3964r.cpp comm/camcon/table/link_pair.h comm/camcon/table/link_pair.cpp LIBS cambench_comm)
cambench_add_test(tst_table_rk512 SOURCES comm/camcon/table/tst_rk512.cpp LIBS cambench_comm)
cambench_add_test(tst_table_map SOURCES comm/camcon/table/tst_table_map.cpp LIBS cambench_comm)
cambench_add_test(tst_table_short_commands SOURCES comm/camcon/table/tst_short_commands.cpp LIBS cambench_comm)
include(${CMAKE_CURRENT_LIST_DIR}/../../../fuzz/link_3964r.cmake)
cambench_add_test(tst_table_backend SOURCES comm/camcon/table/tst_table_backend.cpp LIBS cambench_comm)
