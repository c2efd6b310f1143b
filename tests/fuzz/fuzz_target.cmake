# cambench_add_fuzz_target(NAME <name> FUZZ_SOURCE <file> REPLAY_MAIN <file>
#                          SOURCES_PROPERTY <global property>)
#
# Adds, for a fuzz function (FUZZ_SOURCE, defining LLVMFuzzerTestOneInput):
# - <name>_replay, always built and run by ctest: the function over a fixed
#   corpus and fixed-seed random inputs (REPLAY_MAIN with fuzz_replay.cpp);
# - <name>, with CAMBENCH_FUZZ (clang only): the libFuzzer target. The sources
#   under test, listed in the global property SOURCES_PROPERTY, are compiled
#   into it so that they carry the fuzzer's coverage instrumentation and the
#   sanitizers.
# File names are relative to this folder.
include_guard(GLOBAL)

function(cambench_add_fuzz_target)
  cmake_parse_arguments(F "" "NAME;FUZZ_SOURCE;REPLAY_MAIN;SOURCES_PROPERTY" "" ${ARGN})
  set(dir ${CMAKE_CURRENT_FUNCTION_LIST_DIR})

  add_executable(${F_NAME}_replay
    ${dir}/${F_FUZZ_SOURCE} ${dir}/${F_REPLAY_MAIN} ${dir}/fuzz_replay.cpp)
  target_link_libraries(${F_NAME}_replay PRIVATE cambench_comm)
  add_test(NAME ${F_NAME}_replay COMMAND ${F_NAME}_replay)
  set_tests_properties(${F_NAME}_replay PROPERTIES TIMEOUT 300)

  if(NOT CAMBENCH_FUZZ)
    return()
  endif()
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "CAMBENCH_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++)")
  endif()
  get_property(sources GLOBAL PROPERTY ${F_SOURCES_PROPERTY})
  # An empty list links only at the fuzz build in CI; say so at configure time.
  if(NOT sources)
    message(FATAL_ERROR "${F_NAME}: the sources under test are not known (property ${F_SOURCES_PROPERTY})")
  endif()
  set(flags -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_executable(${F_NAME} ${dir}/${F_FUZZ_SOURCE} ${sources})
  target_include_directories(${F_NAME} PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_options(${F_NAME} PRIVATE ${flags})
  target_link_options(${F_NAME} PRIVATE ${flags})
  target_link_libraries(${F_NAME} PRIVATE Qt6::Core)
endfunction()
