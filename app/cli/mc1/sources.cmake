# The MC-1 family's command group `mc` of cambench-cli (paths relative to app/).
target_sources(cambench-cli PRIVATE
  cli/mc1/mc1_commands.h
  cli/mc1/mc1_commands.cpp
  cli/mc1/mc1_motion_commands.cpp
  cli/mc1/mc1_backup_commands.cpp
)
