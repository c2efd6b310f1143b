# Fuzzing of the 3964R state machine (comm/camcon/table/link_3964r). Included
# from tests/comm/table/tests.cmake; paths are relative to this file.
get_property(CAMBENCH_TABLE_LINK_SOURCES GLOBAL PROPERTY CAMBENCH_TABLE_LINK_SOURCES)

# Always built: the fuzz function over a fixed corpus and fixed-seed random
# inputs, so that every normal build and `ctest` exercise it.
add_executable(fuzz_link_3964r_replay
  ${CMAKE_CURRENT_LIST_DIR}/fuzz_link_3964r.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fuzz_link_3964r_replay_main.cpp)
target_link_libraries(fuzz_link_3964r_replay PRIVATE cambench_comm)
add_test(NAME fuzz_link_3964r_replay COMMAND fuzz_link_3964r_replay)
set_tests_properties(fuzz_link_3964r_replay PROPERTIES TIMEOUT 300)

# libFuzzer target: clang only. The link sources are compiled into it so
# that they carry the fuzzer's coverage instrumentation and the sanitizers.
if(CAMBENCH_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "CAMBENCH_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++)")
  endif()
  set(CAMBENCH_LINK_FUZZ_FLAGS -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_executable(fuzz_link_3964r ${CMAKE_CURRENT_LIST_DIR}/fuzz_link_3964r.cpp ${CAMBENCH_TABLE_LINK_SOURCES})
  target_include_directories(fuzz_link_3964r PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_options(fuzz_link_3964r PRIVATE ${CAMBENCH_LINK_FUZZ_FLAGS})
  target_link_options(fuzz_link_3964r PRIVATE ${CAMBENCH_LINK_FUZZ_FLAGS})
  target_link_libraries(fuzz_link_3964r PRIVATE Qt6::Core)
endif()
