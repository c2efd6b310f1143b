# cambench-sim: a simulated device (or a machine of several) on pseudo-terminals or TCP ports.
add_executable(cambench-sim
  sim/main.cpp
  sim/signal_quitter.cpp
  sim/signal_quitter.h
  sim/sim_machine.cpp
  sim/sim_machine.h
  sim/sim_options.cpp
  sim/sim_options.h
)
target_link_libraries(cambench-sim PRIVATE cambench_registry cambench_sim)
install(TARGETS cambench-sim)  # to bin/ under the install prefix
