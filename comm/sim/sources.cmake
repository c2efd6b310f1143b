target_sources(cambench_comm PRIVATE
)
