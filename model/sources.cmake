target_sources(cambench_model PRIVATE
  result.h
  cam_program.h
  device_info.h
  dead_times.h
  user.h
  plc_network.h
  eeprom_image.h
  system_settings.h
)
