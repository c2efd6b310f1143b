# The desktop application: main() only wires the libraries together.
# The registrations with each family's GUI part (app/registry/sources.cmake),
# also linked by the GUI tests instead of cambench_registry.
add_library(cambench_gui_registry ${CAMBENCH_LIBRARY_TYPE} ${CAMBENCH_FAMILY_PARTS})
target_compile_definitions(cambench_gui_registry PRIVATE CAMBENCH_PARTS_GUI)
target_link_libraries(cambench_gui_registry PUBLIC cambench_family_parts cambench_ui)

add_executable(cambench gui/main.cpp)
target_link_libraries(cambench PRIVATE cambench_ui cambench_gui_registry)
install(TARGETS cambench)  # to bin/ under the install prefix
