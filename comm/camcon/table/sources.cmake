# The byte level of the CamCon table interface: 3964R, RK512, the table
# map, the cam-track rules and the short commands 0x01..0x07. Pure code, no I/O.
set(CAMBENCH_TABLE_LINK_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/frame_3964r.cpp
  ${CMAKE_CURRENT_LIST_DIR}/link_3964r.cpp
)
# fuzz_link_3964r compiles these itself, with sanitizer coverage.
set_property(GLOBAL PROPERTY CAMBENCH_TABLE_LINK_SOURCES ${CAMBENCH_TABLE_LINK_SOURCES})

target_sources(cambench_comm PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/frame_3964r.h
  ${CMAKE_CURRENT_LIST_DIR}/link_3964r.h
  ${CMAKE_CURRENT_LIST_DIR}/rk512.h
  ${CMAKE_CURRENT_LIST_DIR}/rk512.cpp
  ${CMAKE_CURRENT_LIST_DIR}/rk512_planner.h
  ${CMAKE_CURRENT_LIST_DIR}/rk512_planner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_map.h
  ${CMAKE_CURRENT_LIST_DIR}/table_map.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cam_track_words.h
  ${CMAKE_CURRENT_LIST_DIR}/cam_track_words.cpp
  ${CMAKE_CURRENT_LIST_DIR}/short_commands.h
  ${CMAKE_CURRENT_LIST_DIR}/short_commands.cpp
  ${CMAKE_CURRENT_LIST_DIR}/short_client.h
  ${CMAKE_CURRENT_LIST_DIR}/short_client.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_logging.h
  ${CMAKE_CURRENT_LIST_DIR}/table_logging.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_backend.h
  ${CMAKE_CURRENT_LIST_DIR}/table_backend.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_link.h
  ${CMAKE_CURRENT_LIST_DIR}/table_link.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_settings_map.h
  ${CMAKE_CURRENT_LIST_DIR}/table_settings_map.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_word_block.h
  ${CMAKE_CURRENT_LIST_DIR}/table_word_block.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_camcon.h
  ${CMAKE_CURRENT_LIST_DIR}/table_camcon.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_camcon_info.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_camcon_cams.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_camcon_dead_times.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_camcon_settings.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_camcon_plc.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_camcon_extras.cpp
  ${CMAKE_CURRENT_LIST_DIR}/table_protocol.h
  ${CMAKE_CURRENT_LIST_DIR}/table_protocol.cpp
  ${CAMBENCH_TABLE_LINK_SOURCES}
)
