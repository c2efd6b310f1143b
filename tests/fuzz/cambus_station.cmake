# Fuzzing of the Cam-BUS receiver (comm/camcon/cambus: the station and the
# payload parser). Included from tests/comm/camcon/tests.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/fuzz_target.cmake)
cambench_add_fuzz_target(NAME fuzz_cambus_station
  FUZZ_SOURCE fuzz_cambus_station.cpp
  REPLAY_MAIN fuzz_cambus_station_replay_main.cpp
  SOURCES_PROPERTY CAMBENCH_CAMBUS_STATION_SOURCES)
