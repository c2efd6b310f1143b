# The camcon family's end-to-end tests (paths relative to tests/), and its
# CamConClient against the in-process simulator.
cambench_add_test(tst_operations_camcon_client
  SOURCES e2e/camcon/tst_camcon_client.cpp usecases/camcon/sim_bench.h usecases/camcon/sim_bench.cpp
  LIBS cambench_sim)
cambench_add_e2e_test(tst_e2e_eeprom e2e/camcon/tst_e2e_eeprom.cpp)
cambench_add_e2e_test(tst_e2e_table_camcon e2e/camcon/tst_table_camcon.cpp)
cambench_add_e2e_test(tst_e2e_table_sections e2e/camcon/tst_e2e_table_sections.cpp)
cambench_add_e2e_test(tst_e2e_detect e2e/camcon/tst_e2e_detect.cpp)
