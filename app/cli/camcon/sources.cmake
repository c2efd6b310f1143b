# The CamCon's commands of cambench-cli (paths relative to app/).
target_sources(cambench-cli PRIVATE
  cli/camcon/camcon_commands.h
  cli/camcon/camcon_commands.cpp
  cli/camcon/device_commands.cpp
  cli/camcon/cam_commands.cpp
  cli/camcon/table_commands.cpp
  cli/camcon/config_commands.cpp
  cli/camcon/eeprom_commands.cpp
  cli/camcon/project_commands.cpp
  cli/camcon/diff_command.cpp
  cli/camcon/timing_command.cpp
  cli/camcon/line_commands.cpp
  cli/camcon/coupling_commands.cpp
  cli/camcon/table_section_commands.cpp
  cli/camcon/cli_format.h
  cli/camcon/cli_format.cpp
  cli/camcon/write_output.h
  cli/camcon/write_output.cpp
)
