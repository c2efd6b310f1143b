# Fuzzing of the 3964R state machine (comm/camcon/table/link_3964r). Included
# from tests/comm/camcon/table/tests.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/fuzz_target.cmake)
cambench_add_fuzz_target(NAME fuzz_link_3964r
  FUZZ_SOURCE fuzz_link_3964r.cpp
  REPLAY_MAIN fuzz_link_3964r_replay_main.cpp
  SOURCES_PROPERTY CAMBENCH_TABLE_LINK_SOURCES)
