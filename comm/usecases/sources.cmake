target_sources(cambench_usecases PRIVATE
  use_case_progress.h
  use_case_progress.cpp
  write_plan.h
  write_plan.cpp
  write_report.h
  write_report.cpp
  plan_check.h
  plan_check.cpp
  write_items.h
  write_items.cpp
  read_everything.h
  read_everything.cpp
  backup_restore.h
  backup_restore.cpp
  line_backup.h
  line_backup.cpp
)
