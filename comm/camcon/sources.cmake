# The CamCon family: the device interface both CamCon protocols implement.
target_sources(cambench_comm PRIVATE
  camcon/camcon_device.h
  camcon/camcon_device.cpp
  camcon/camcon_family.h
  camcon/camcon_family.cpp
)
