target_sources(cambench_ui PRIVATE
)
