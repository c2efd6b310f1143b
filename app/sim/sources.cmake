# cambench-sim: the simulated CamCon on a pseudo-terminal or a TCP port.
add_executable(cambench-sim
  sim/main.cpp
  sim/signal_quitter.cpp
  sim/signal_quitter.h
)
target_link_libraries(cambench-sim PRIVATE cambench_registry cambench_sim)
install(TARGETS cambench-sim)  # to bin/ under the install prefix
