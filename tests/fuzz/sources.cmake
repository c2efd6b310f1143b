# Fuzzing of the ASCII frame decoder (comm/camcon/ascii/stream_decoder).
get_property(CAMBENCH_ASCII_DECODER_SOURCES GLOBAL PROPERTY CAMBENCH_ASCII_DECODER_SOURCES)

# Always built: the fuzz function over a fixed corpus and fixed-seed random
# inputs, so that every normal build and `ctest` exercise it.
add_executable(fuzz_stream_decoder_replay fuzz_stream_decoder.cpp fuzz_replay_main.cpp)
target_link_libraries(fuzz_stream_decoder_replay PRIVATE cambench_comm)
add_test(NAME fuzz_stream_decoder_replay COMMAND fuzz_stream_decoder_replay)
set_tests_properties(fuzz_stream_decoder_replay PROPERTIES TIMEOUT 300)

# libFuzzer target: clang only. The protocol sources are compiled into it so
# that they carry the fuzzer's coverage instrumentation and the sanitizers.
if(CAMBENCH_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "CAMBENCH_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++)")
  endif()
  set(CAMBENCH_FUZZ_FLAGS -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  # An empty list links only at the fuzz build in CI; say so at configure time.
  if(NOT CAMBENCH_ASCII_DECODER_SOURCES)
    message(FATAL_ERROR "fuzz_stream_decoder: the ASCII decoder sources are not known (property CAMBENCH_ASCII_DECODER_SOURCES)")
  endif()
  add_executable(fuzz_stream_decoder fuzz_stream_decoder.cpp ${CAMBENCH_ASCII_DECODER_SOURCES})
  target_include_directories(fuzz_stream_decoder PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_options(fuzz_stream_decoder PRIVATE ${CAMBENCH_FUZZ_FLAGS})
  target_link_options(fuzz_stream_decoder PRIVATE ${CAMBENCH_FUZZ_FLAGS})
  target_link_libraries(fuzz_stream_decoder PRIVATE Qt6::Core)
endif()
