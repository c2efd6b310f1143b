# The camcon family's end-to-end tests (paths relative to tests/), and its
# CamConClient against the in-process simulator.
cambench_add_test(tst_operations_camcon_client
  SOURCES e2e/camcon/tst_camcon_client.cpp usecases/camcon/sim_bench.h usecases/camcon/sim_bench.cpp
  LIBS cambench_sim)
cambench_add_e2e_test(tst_e2e_eeprom e2e/camcon/tst_e2e_eeprom.cpp)
# A backup of the older format (version 1, the blocks alone), as CamBench
# wrote it before issue 36: it still restores byte for byte.
target_compile_definitions(tst_e2e_eeprom PRIVATE
  CAMBENCH_E2E_CAMCON_DATA="${PROJECT_SOURCE_DIR}/tests/e2e/camcon/data")
cambench_add_e2e_test(tst_e2e_table_camcon e2e/camcon/tst_table_camcon.cpp)
cambench_add_e2e_test(tst_e2e_table_sections e2e/camcon/tst_e2e_table_sections.cpp)
cambench_add_e2e_test(tst_e2e_detect e2e/camcon/tst_e2e_detect.cpp)
