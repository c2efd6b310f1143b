# The MC-1 family's use cases, shared by the GUI and the CLI: backup,
# verify and restore of variables, flags and memory.
target_sources(cambench_usecases PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/mc1_backup_restore.h
  ${CMAKE_CURRENT_LIST_DIR}/mc1_backup_restore.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mc1_backup_diff.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mc1_backup_part.h
  ${CMAKE_CURRENT_LIST_DIR}/mc1_backup_part.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mc1_check.h
  ${CMAKE_CURRENT_LIST_DIR}/mc1_check.cpp
)
