# The settings table's texts live in model/ without translation markers;
# this tool lists them for lupdate (setting_texts.cpp).
add_executable(cambench_dump_setting_texts EXCLUDE_FROM_ALL ${CMAKE_CURRENT_LIST_DIR}/dump_setting_texts.cpp)
target_link_libraries(cambench_dump_setting_texts PRIVATE cambench_model)
add_custom_target(update_setting_texts
  COMMAND cambench_dump_setting_texts ${CMAKE_CURRENT_SOURCE_DIR}/setting_texts.cpp
  COMMAND ${CMAKE_COMMAND} -E echo "Now run the target update_translations."
  COMMENT "Listing the settings texts for lupdate")
