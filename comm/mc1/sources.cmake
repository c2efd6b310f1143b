# The MICRO DESIGN MC100/MC200 (MC-1) family: its protocol core (telegrams of
# the four variants, answers, address arithmetic), the device (Mc1Device,
# Mc1Controller) and the protocol's registration.
# What the MC-1 answer decoder is made of: fuzz_mc1_decoder compiles these
# itself, with sanitizer coverage.
set(CAMBENCH_MC1_DECODER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/mc1_variant.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mc1_telegram.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mc1_catalogue.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mc1_backend.cpp
)
set_property(GLOBAL PROPERTY CAMBENCH_MC1_DECODER_SOURCES ${CAMBENCH_MC1_DECODER_SOURCES})

target_sources(cambench_comm PRIVATE
  mc1/mc1_family.h
  mc1/mc1_family.cpp
  mc1/mc1_variant.h
  mc1/mc1_variant.cpp
  mc1/mc1_telegram.h
  mc1/mc1_telegram.cpp
  mc1/mc1_catalogue.h
  mc1/mc1_catalogue.cpp
  mc1/mc1_address.h
  mc1/mc1_address.cpp
  mc1/mc1_ascii.h
  mc1/mc1_ascii.cpp
  mc1/mc1_backend.h
  mc1/mc1_backend.cpp
  mc1/mc1_link.h
  mc1/mc1_link.cpp
  mc1/mc1_parameters.h
  mc1/mc1_parameters.cpp
  mc1/mc1_device.h
  mc1/mc1_device.cpp
  mc1/mc1_controller.h
  mc1/mc1_controller.cpp
  mc1/mc1_controller_motion.cpp
  mc1/mc1_controller_identity.cpp
  mc1/mc1_axis_motion.h
  mc1/mc1_axis_motion.cpp
  mc1/mc1_protocol.h
  mc1/mc1_protocol.cpp
  mc1/mc1_ascii_backend.h
  mc1/mc1_ascii_backend.cpp
  mc1/mc1_ascii_controller.h
  mc1/mc1_ascii_controller.cpp
)
