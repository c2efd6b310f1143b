# The Parker Compax3 family: the ASCII object protocol (syntax, framing),
# the objects and bits CamBench uses, the device (Compax3Device,
# Compax3Drive) and the protocols' registration.
# What the Compax3 answer parser is made of: fuzz_compax3_reply compiles
# these itself, with sanitizer coverage.
set(CAMBENCH_COMPAX3_REPLY_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/compax3_syntax.cpp
  ${CMAKE_CURRENT_LIST_DIR}/compax3_backend.cpp
  ${CMAKE_CURRENT_LIST_DIR}/../engine/cr_line_backend.cpp
  ${PROJECT_SOURCE_DIR}/model/compax3/compax3_object.cpp
  ${PROJECT_SOURCE_DIR}/model/compax3/compax3_refusals.cpp
  # The built-in dictionary the refusal table reads (configure_file in
  # model/compax3/sources.cmake).
  ${PROJECT_BINARY_DIR}/model/compax3_builtin_objects.cpp
)
set_property(GLOBAL PROPERTY CAMBENCH_COMPAX3_REPLY_SOURCES ${CAMBENCH_COMPAX3_REPLY_SOURCES})

target_sources(cambench_comm PRIVATE
  compax3/compax3_family.h
  compax3/compax3_family.cpp
  compax3/compax3_syntax.h
  compax3/compax3_syntax.cpp
  compax3/compax3_backend.h
  compax3/compax3_backend.cpp
  compax3/compax3_objects.h
  compax3/compax3_objects.cpp
  compax3/compax3_device.h
  compax3/compax3_device.cpp
  compax3/compax3_drive.h
  compax3/compax3_drive.cpp
  compax3/compax3_drive_motion.cpp
  compax3/compax3_drive_stop.cpp
  compax3/compax3_protocol.h
  compax3/compax3_protocol.cpp
)
