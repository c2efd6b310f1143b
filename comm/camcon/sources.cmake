# The CamCon family: the device interface both CamCon protocols implement.
target_sources(cambench_comm PRIVATE
  camcon/camcon_device.h
  camcon/camcon_device.cpp
  camcon/camcon_family.h
  camcon/camcon_family.cpp
)
# Its protocols: ASCII (Standard, Multiuser), the table interface (3964R),
# the Cam-BUS.
include(${CMAKE_CURRENT_LIST_DIR}/ascii/sources.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/table/sources.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/cambus/sources.cmake)
