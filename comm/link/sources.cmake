target_sources(cambench_comm PRIVATE
  link/protocol_link.h
)
