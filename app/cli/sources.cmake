# cambench-cli: the command-line tool (paths relative to app/).
add_executable(cambench-cli
  cli/main.cpp
  cli/exit_codes.h
  cli/cli_options.h
  cli/cli_options.cpp
  cli/cli_output.h
  cli/cli_output.cpp
  cli/progress_bar.h
  cli/progress_bar.cpp
  cli/traffic_log_file.h
  cli/traffic_log_file.cpp
  cli/cli_session.h
  cli/cli_session.cpp
  cli/commands.h
  cli/commands.cpp
  cli/port_commands.cpp
  cli/detect_command.cpp
  cli/cli_families.cpp
)
# The CamCon's command groups.
include(${CMAKE_CURRENT_LIST_DIR}/camcon/sources.cmake)
target_link_libraries(cambench-cli PRIVATE cambench_registry cambench_usecases cambench_comm cambench_model Qt6::Core)
install(TARGETS cambench-cli)  # to bin/ under the install prefix
