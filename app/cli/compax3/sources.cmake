# The Compax3 family's command group `c3` of cambench-cli (paths relative to app/).
target_sources(cambench-cli PRIVATE
  cli/compax3/compax3_commands.h
  cli/compax3/compax3_commands.cpp
  cli/compax3/compax3_object_commands.cpp
  cli/compax3/compax3_motion_commands.cpp
  cli/compax3/compax3_parameter_commands.cpp
)
