target_sources(cambench_comm PRIVATE
  transport/transport.h
)
