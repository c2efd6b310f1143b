target_sources(cambench_comm PRIVATE
  operations/camcon_client.h
)
