# The protocol-neutral device seam: protocol settings, device connections,
# the protocol and family registries.
target_sources(cambench_comm PRIVATE
  device/connection_settings.h
  device/device_connection.h
  device/motion_control.h
  device/progress.h
  device/job.h
  device/job_runner.h
  device/error_context.h
  device/protocol_settings.h
  device/protocol_option.h
  device/protocol_options.h
  device/protocol_options.cpp
  device/protocol_registry.h
  device/protocol_registry.cpp
  device/family_registry.h
  device/id_registry.h
  device/family_registry.cpp
)
