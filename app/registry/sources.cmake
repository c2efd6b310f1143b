# The frame of a family's registration (FamilyParts, registering them, the
# startup check), linked by every program and test.
add_library(cambench_family_parts ${CAMBENCH_LIBRARY_TYPE}
  registry/family_parts.h
  registry/family_parts.cpp
)
target_link_libraries(cambench_family_parts PUBLIC cambench_comm cambench_sim cambench_usecases)

# What CamBench can talk to: the transports and the built-in families,
# each through its FamilyParts (registry/<family>/sources.cmake lists its
# parts file). The same files are compiled once per kind of program, each
# with the parts that program links: cambench_registry here (no GUI, no
# CLI: cambench-sim, the bench, the tests without widgets), the GUI's in
# app/gui/sources.cmake (CAMBENCH_PARTS_GUI), the CLI's in
# app/cli/sources.cmake (CAMBENCH_PARTS_CLI). A program links one of them.
set(CAMBENCH_FAMILY_PARTS
  registry/builtin_registry.h
  registry/builtin_registry.cpp
)
cambench_include_family_lists(${CMAKE_CURRENT_LIST_DIR} sources.cmake)
add_library(cambench_registry ${CAMBENCH_LIBRARY_TYPE} ${CAMBENCH_FAMILY_PARTS})
target_link_libraries(cambench_registry PUBLIC cambench_family_parts)
