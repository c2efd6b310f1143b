# The Compax3 family's use cases, shared by the GUI and the CLI: parameter
# sets read, compared and written back.
target_sources(cambench_usecases PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/compax3_parameters.h
  ${CMAKE_CURRENT_LIST_DIR}/compax3_parameters.cpp
  ${CMAKE_CURRENT_LIST_DIR}/compax3_backup_diff.cpp
  ${CMAKE_CURRENT_LIST_DIR}/compax3_backup_part.h
  ${CMAKE_CURRENT_LIST_DIR}/compax3_backup_part.cpp
  ${CMAKE_CURRENT_LIST_DIR}/compax3_read_objects.h
  ${CMAKE_CURRENT_LIST_DIR}/compax3_read_objects.cpp
  ${CMAKE_CURRENT_LIST_DIR}/compax3_check.h
  ${CMAKE_CURRENT_LIST_DIR}/compax3_check.cpp
)
