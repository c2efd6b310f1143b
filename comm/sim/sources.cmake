# The simulator host (in-process port, pseudo-terminal and TCP servers,
# pacing, shared faults, the registry of family simulators). Each family's
# simulated device is listed in its own folder (<family>/sources.cmake).
target_sources(cambench_sim PRIVATE
  sim_endpoint.h
  sim_faults.cpp
  sim_faults.h
  sim_injections.cpp
  sim_injections.h
  sim_log.cpp
  sim_log.h
  sim_output.h
  sim_pacer.cpp
  sim_pacer.h
  sim_pty_server.cpp
  sim_pty_server.h
  sim_reply_scheduler.cpp
  sim_reply_scheduler.h
  sim_shaft.cpp
  sim_shaft.h
  sim_tcp_server.cpp
  sim_tcp_server.h
  sim_transport.cpp
  sim_transport.h
  simulator_registry.cpp
  simulator_registry.h
)
