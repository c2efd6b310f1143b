# The camcon family's use cases against its in-process simulator (paths
# relative to tests/).
add_library(cambench_test_sim_bench OBJECT usecases/camcon/sim_bench.h usecases/camcon/sim_bench.cpp)
target_link_libraries(cambench_test_sim_bench PRIVATE cambench_usecases cambench_sim)
function(cambench_add_usecase_test name)
  cambench_add_test(${name} SOURCES ${ARGN} $<TARGET_OBJECTS:cambench_test_sim_bench>
                    LIBS cambench_usecases cambench_sim)
endfunction()
cambench_add_usecase_test(tst_usecase_write_items usecases/camcon/tst_write_items.cpp)
cambench_add_usecase_test(tst_usecase_read_everything usecases/camcon/tst_read_everything.cpp)
cambench_add_usecase_test(tst_usecase_backup usecases/camcon/tst_backup.cpp)
cambench_add_usecase_test(tst_usecase_check usecases/camcon/tst_check.cpp)
cambench_add_usecase_test(tst_usecase_program_read usecases/camcon/tst_program_read.cpp)
