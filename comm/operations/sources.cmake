target_sources(cambench_comm PRIVATE
  operations/camcon_client.h
  operations/client_support.h
  operations/client_info.cpp
  operations/client_cams.cpp
  operations/client_names.cpp
  operations/client_settings.cpp
  operations/settings_commands.h
  operations/settings_commands.cpp
  operations/client_users.cpp
  operations/client_plc.cpp
  operations/client_eeprom.cpp
  operations/client_scan.cpp
)
