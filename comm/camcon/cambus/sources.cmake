# Cam-BUS, the CamCon's token bus (docs/protocols/cambus.md): the wire format, one
# bus user's state machine (the PC's and every simulated user's), the
# framing backend that carries CamCon ASCII frames in blocks, the CamCon
# over it and the protocol's registration.
# What the Cam-BUS receiver is made of: fuzz_cambus_station compiles these
# itself, with sanitizer coverage.
set(CAMBENCH_CAMBUS_STATION_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/cambus_block.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cambus_station.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cambus_payload.cpp
  ${CMAKE_CURRENT_LIST_DIR}/../ascii/frame.cpp
  ${CMAKE_CURRENT_LIST_DIR}/../../transport/break_marks.cpp
)
set_property(GLOBAL PROPERTY CAMBENCH_CAMBUS_STATION_SOURCES ${CAMBENCH_CAMBUS_STATION_SOURCES})

target_sources(cambench_comm PRIVATE
  camcon/cambus/cambus_block.h
  camcon/cambus/cambus_block.cpp
  camcon/cambus/cambus_payload.h
  camcon/cambus/cambus_payload.cpp
  camcon/cambus/cambus_view.h
  camcon/cambus/cambus_station.h
  camcon/cambus/cambus_station.cpp
  camcon/cambus/cambus_backend.h
  camcon/cambus/cambus_backend.cpp
  camcon/cambus/cambus_camcon.h
  camcon/cambus/cambus_camcon.cpp
  camcon/cambus/cambus_protocol.h
  camcon/cambus/cambus_protocol.cpp
)
