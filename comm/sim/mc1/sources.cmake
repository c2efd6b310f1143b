# The simulated MC-1 controller of each variant, its binary and ASCII lines
# and its registration; paths relative to comm/sim/.
target_sources(cambench_sim PRIVATE
  mc1/sim_mc1_controller.cpp
  mc1/sim_mc1_controller.h
  mc1/sim_mc1_line.cpp
  mc1/sim_mc1_line.h
  mc1/mc1_simulator.cpp
  mc1/mc1_simulator.h
  mc1/sim_mc1_ascii_line.cpp
  mc1/sim_mc1_ascii_line.h
)
