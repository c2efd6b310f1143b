# cambench-cli: the command-line tool (paths relative to app/).
# The front every family shares - options, exit codes, output, the session,
# the command registry, the shell's own commands - is a library, so that a
# test can host a family of its own in it.
add_library(cambench_cli_front ${CAMBENCH_LIBRARY_TYPE}
  cli/exit_codes.h
  cli/cli_options.h
  cli/cli_options.cpp
  cli/cli_output.h
  cli/cli_output.cpp
  cli/outcome_output.h
  cli/outcome_output.cpp
  cli/backup_output.h
  cli/backup_output.cpp
  cli/progress_bar.h
  cli/progress_bar.cpp
  cli/traffic_log_file.h
  cli/traffic_log_file.cpp
  cli/cli_session.h
  cli/cli_session.cpp
  cli/interrupt_watch.h
  cli/interrupt_watch.cpp
  cli/commands.h
  cli/commands.cpp
  cli/command_line.h
  cli/command_line.cpp
  cli/port_commands.cpp
  cli/detect_command.cpp
  cli/check_command.cpp
  cli/help_command.cpp
  cli/machine_command.h
  cli/machine_command.cpp
  cli/machine_backup.cpp
  cli/machine_history.h
  cli/machine_history.cpp
  cli/machine_parallel.h
  cli/machine_parallel.cpp
)
target_include_directories(cambench_cli_front PUBLIC ${PROJECT_SOURCE_DIR})
target_link_libraries(cambench_cli_front PUBLIC cambench_usecases cambench_comm cambench_model Qt6::Core)

add_executable(cambench-cli
  cli/main.cpp
)
# Each family's command groups, listed in its folder.
cambench_include_family_lists(${CMAKE_CURRENT_LIST_DIR} sources.cmake)
# The registrations with each family's CLI part (app/registry/sources.cmake):
# objects of cambench-cli itself, whose command groups they name.
add_library(cambench_cli_registry OBJECT ${CAMBENCH_FAMILY_PARTS})
target_compile_definitions(cambench_cli_registry PRIVATE CAMBENCH_PARTS_CLI)
target_link_libraries(cambench_cli_registry PUBLIC cambench_cli_front cambench_family_parts)
target_link_libraries(cambench-cli PRIVATE cambench_cli_registry cambench_cli_front cambench_family_parts cambench_usecases cambench_comm cambench_model Qt6::Core)
install(TARGETS cambench-cli)  # to bin/ under the install prefix
