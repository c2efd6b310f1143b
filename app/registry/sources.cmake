# What CamBench can talk to: transports, protocols, simulators, and the
# families' checks. Linked by every program and by the tests that open
# connections.
add_library(cambench_registry ${CAMBENCH_LIBRARY_TYPE}
  registry/builtin_registry.h
  registry/builtin_registry.cpp
)
target_link_libraries(cambench_registry PUBLIC cambench_comm cambench_sim cambench_usecases)
