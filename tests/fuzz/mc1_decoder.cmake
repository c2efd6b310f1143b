# Fuzzing of the MC-1 answer decoder (comm/mc1/mc1_backend). Included from
# tests/comm/mc1/tests.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/fuzz_target.cmake)
cambench_add_fuzz_target(NAME fuzz_mc1_decoder
  FUZZ_SOURCE fuzz_mc1_decoder.cpp
  REPLAY_MAIN fuzz_mc1_decoder_replay_main.cpp
  SOURCES_PROPERTY CAMBENCH_MC1_DECODER_SOURCES)
