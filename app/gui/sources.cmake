# The desktop application: main() only wires the libraries together.
add_executable(cambench gui/main.cpp)
target_link_libraries(cambench PRIVATE cambench_ui cambench_registry)
install(TARGETS cambench)  # to bin/ under the install prefix
