# The use-case frame every family shares: progress and cancel, the outcome
# of one written item and the tally of a write, and Detect (which family
# answers on a port), who answers on a device's line.
target_sources(cambench_usecases PRIVATE
  use_case_progress.h
  use_case_progress.cpp
  item_outcome.h
  item_outcome.cpp
  detect_device.h
  detect_device.cpp
  device_check.h
  device_check.cpp
  family_backup.h
  family_backup.cpp
  machine_backup.h
  machine_backup.cpp
  line_answer.h
  line_answer.cpp
  machine_history.h
  machine_history.cpp
)
