# The CamCon's use cases, shared by the GUI and the CLI: read everything,
# the one write path (plan, check, write, report), backup and restore, the
# line backup, the S7-CP340 short coupling.
target_sources(cambench_usecases PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/write_plan.h
  ${CMAKE_CURRENT_LIST_DIR}/write_plan.cpp
  ${CMAKE_CURRENT_LIST_DIR}/write_report.h
  ${CMAKE_CURRENT_LIST_DIR}/write_report.cpp
  ${CMAKE_CURRENT_LIST_DIR}/value_text.h
  ${CMAKE_CURRENT_LIST_DIR}/value_text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plan_check.h
  ${CMAKE_CURRENT_LIST_DIR}/plan_check.cpp
  ${CMAKE_CURRENT_LIST_DIR}/write_items.h
  ${CMAKE_CURRENT_LIST_DIR}/write_items.cpp
  ${CMAKE_CURRENT_LIST_DIR}/read_everything.h
  ${CMAKE_CURRENT_LIST_DIR}/read_everything.cpp
  ${CMAKE_CURRENT_LIST_DIR}/program_read.h
  ${CMAKE_CURRENT_LIST_DIR}/program_read.cpp
  ${CMAKE_CURRENT_LIST_DIR}/backup_restore.h
  ${CMAKE_CURRENT_LIST_DIR}/backup_restore.cpp
  ${CMAKE_CURRENT_LIST_DIR}/camcon_backup_part.h
  ${CMAKE_CURRENT_LIST_DIR}/camcon_backup_part.cpp
  ${CMAKE_CURRENT_LIST_DIR}/line_backup.h
  ${CMAKE_CURRENT_LIST_DIR}/line_backup.cpp
  ${CMAKE_CURRENT_LIST_DIR}/short_coupling.h
  ${CMAKE_CURRENT_LIST_DIR}/short_coupling.cpp
  ${CMAKE_CURRENT_LIST_DIR}/camcon_check.h
  ${CMAKE_CURRENT_LIST_DIR}/camcon_check.cpp
  ${CMAKE_CURRENT_LIST_DIR}/camcon_check_parts.h
  ${CMAKE_CURRENT_LIST_DIR}/camcon_check_ascii.cpp
  ${CMAKE_CURRENT_LIST_DIR}/camcon_check_table.cpp
)
