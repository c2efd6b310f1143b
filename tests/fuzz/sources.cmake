# Fuzzing of the ASCII frame decoder (comm/camcon/ascii/stream_decoder).
include(${CMAKE_CURRENT_LIST_DIR}/fuzz_target.cmake)
cambench_add_fuzz_target(NAME fuzz_stream_decoder
  FUZZ_SOURCE fuzz_stream_decoder.cpp
  REPLAY_MAIN fuzz_replay_main.cpp
  SOURCES_PROPERTY CAMBENCH_ASCII_DECODER_SOURCES)
