# The desktop application: main() only wires the libraries together.
# The GUI's registrations (one line per protocol widget), also linked by
# the GUI tests.
add_library(cambench_gui_registry ${CAMBENCH_LIBRARY_TYPE} gui/gui_registry.h gui/gui_registry.cpp)
target_link_libraries(cambench_gui_registry PUBLIC cambench_ui)

add_executable(cambench gui/main.cpp)
target_link_libraries(cambench PRIVATE cambench_ui cambench_gui_registry cambench_registry)
install(TARGETS cambench)  # to bin/ under the install prefix
