# The MC-1 family's files: backup and project; paths relative to model/.
target_sources(cambench_model PRIVATE
  mc1/mc1_family_id.h
  mc1/mc1_backup_file.h
  mc1/mc1_backup_file.cpp
  mc1/mc1_project_file.h
  mc1/mc1_project_file.cpp
)
