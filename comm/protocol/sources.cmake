set(CAMBENCH_PROTOCOL_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/frame.cpp
  ${CMAKE_CURRENT_LIST_DIR}/stream_decoder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/catalogue.cpp
  ${CMAKE_CURRENT_LIST_DIR}/command_codec.cpp
  ${CMAKE_CURRENT_LIST_DIR}/device_errors.cpp
  ${CMAKE_CURRENT_LIST_DIR}/protocol_log.cpp
)
# The fuzz targets compile these files themselves, with sanitizer coverage.
set_property(GLOBAL PROPERTY CAMBENCH_PROTOCOL_SOURCES ${CAMBENCH_PROTOCOL_SOURCES})

target_sources(cambench_comm PRIVATE
  protocol/frame.h
  protocol/stream_decoder.h
  protocol/fields.h
  protocol/catalogue.h
  protocol/command_codec.h
  protocol/device_errors.h
  protocol/protocol_log.h
  ${CAMBENCH_PROTOCOL_SOURCES}
)
