target_sources(cambench_model PRIVATE
  result.h
  walked_list.h
  walked_list.cpp
  machine/machine_file.h
  machine/machine_file.cpp
  model_log.h
  model_log.cpp
  atomic_file.h
  atomic_file.cpp
  file_read.h
  file_read.cpp
  json_reader.h
  json_reader.cpp
  json_file.h
  json_file.cpp
)
