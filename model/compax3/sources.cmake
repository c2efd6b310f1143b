# The Parker Compax3 family's data: objects and values, the object
# dictionary (the shipped compax3-objects.json is built in), parameter files.
file(READ ${CMAKE_CURRENT_LIST_DIR}/compax3-objects.json COMPAX3_OBJECTS_JSON)
configure_file(${CMAKE_CURRENT_LIST_DIR}/compax3_builtin_objects.cpp.in
               ${CMAKE_CURRENT_BINARY_DIR}/compax3_builtin_objects.cpp @ONLY)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_LIST_DIR}/compax3-objects.json)
target_sources(cambench_model PRIVATE
  compax3/compax3_family_id.h
  compax3/compax3_object.h
  compax3/compax3_object.cpp
  compax3/compax3_value.h
  compax3/compax3_value.cpp
  compax3/compax3_dictionary.h
  compax3/compax3_dictionary.cpp
  compax3/compax3_refusals.h
  compax3/compax3_refusals.cpp
  compax3/compax3_builtin_objects.h
  ${CMAKE_CURRENT_BINARY_DIR}/compax3_builtin_objects.cpp
  compax3/compax3_parameter_file.h
  compax3/compax3_parameter_file.cpp
)
