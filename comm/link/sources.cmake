target_sources(cambench_comm PRIVATE
  link/protocol_link.h
  link/protocol_link.cpp
  link/link_logging.h
  link/link_logging.cpp
  link/traffic_mask.h
  link/traffic_mask.cpp
  link/traffic_log.h
  link/traffic_log.cpp
)
