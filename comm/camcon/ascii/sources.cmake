# CamCon ASCII protocol (Standard and Multiuser framing): frames, stream
# decoder, command catalogue and codec, and the CamCon device over it.
set(CAMBENCH_ASCII_DECODER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/frame.cpp
  ${CMAKE_CURRENT_LIST_DIR}/stream_decoder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/catalogue.cpp
  ${CMAKE_CURRENT_LIST_DIR}/command_codec.cpp
  ${CMAKE_CURRENT_LIST_DIR}/device_errors.cpp
  ${CMAKE_CURRENT_LIST_DIR}/protocol_log.cpp
)
# The fuzz targets compile these files themselves, with sanitizer coverage.
set_property(GLOBAL PROPERTY CAMBENCH_ASCII_DECODER_SOURCES ${CAMBENCH_ASCII_DECODER_SOURCES})

target_sources(cambench_comm PRIVATE
  ${CAMBENCH_ASCII_DECODER_SOURCES}
  camcon/ascii/frame.h
  camcon/ascii/stream_decoder.h
  camcon/ascii/fields.h
  camcon/ascii/catalogue.h
  camcon/ascii/command_codec.h
  camcon/ascii/device_errors.h
  camcon/ascii/protocol_log.h
  camcon/ascii/traffic_mask.h
  camcon/ascii/traffic_mask.cpp
  camcon/ascii/ascii_backend.h
  camcon/ascii/ascii_backend.cpp
  camcon/ascii/ascii_link.h
  camcon/ascii/ascii_link.cpp
  camcon/ascii/ascii_camcon.h
  camcon/ascii/ascii_camcon.cpp
  camcon/ascii/ascii_protocol.h
  camcon/ascii/ascii_protocol.cpp
  camcon/ascii/ascii_support.h
  camcon/ascii/ascii_info.cpp
  camcon/ascii/ascii_cams.cpp
  camcon/ascii/ascii_names.cpp
  camcon/ascii/ascii_settings.cpp
  camcon/ascii/settings_commands.h
  camcon/ascii/settings_commands.cpp
  camcon/ascii/ascii_users.cpp
  camcon/ascii/ascii_plc.cpp
  camcon/ascii/ascii_eeprom.cpp
  camcon/ascii/ascii_scan.cpp
)
