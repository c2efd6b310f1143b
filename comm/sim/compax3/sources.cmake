# The simulated Compax3 drive, its RS232/RS485 line and its registration;
# paths relative to comm/sim/.
target_sources(cambench_sim PRIVATE
  compax3/sim_compax3_drive.h
  compax3/sim_compax3_drive.cpp
  compax3/sim_compax3_line.h
  compax3/sim_compax3_line.cpp
  compax3/compax3_simulator.h
  compax3/compax3_simulator.cpp
)
