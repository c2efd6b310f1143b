# What went over the line, as records the engine writes and the traffic
# log, the terminal and the CLI's --log read. Knows no protocol.
target_sources(cambench_comm PRIVATE
  traffic/traffic_entry.h
  traffic/traffic_log.h
  traffic/traffic_log.cpp
)
