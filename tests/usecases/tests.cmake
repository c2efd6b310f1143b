# The use cases against the in-process simulator (paths relative to tests/).
function(cambench_add_usecase_test name)
  cambench_add_test(${name} SOURCES ${ARGN} usecases/sim_bench.h usecases/sim_bench.cpp
                    LIBS cambench_usecases cambench_sim)
endfunction()

cambench_add_usecase_test(tst_usecase_write_items usecases/tst_write_items.cpp)
cambench_add_usecase_test(tst_usecase_read_everything usecases/tst_read_everything.cpp)
cambench_add_usecase_test(tst_usecase_backup usecases/tst_backup.cpp)
cambench_add_usecase_test(tst_usecase_check usecases/tst_check.cpp)
cambench_add_usecase_test(tst_usecase_program_read usecases/tst_program_read.cpp)
# Each family's tests of this area, listed in its folder (tests/usecases/<family>/).
cambench_include_family_lists(${CMAKE_CURRENT_LIST_DIR} tests.cmake)
