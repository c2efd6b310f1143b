# Fuzzing of the Compax3 answer parser (comm/compax3: line framing and
# parseCompax3Reply). Included from tests/comm/compax3/tests.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/fuzz_target.cmake)
cambench_add_fuzz_target(NAME fuzz_compax3_reply
  FUZZ_SOURCE fuzz_compax3_reply.cpp
  REPLAY_MAIN fuzz_compax3_reply_replay_main.cpp
  SOURCES_PROPERTY CAMBENCH_COMPAX3_REPLY_SOURCES)
