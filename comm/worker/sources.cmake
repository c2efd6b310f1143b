target_sources(cambench_comm PRIVATE
  worker/job.h
  worker/comm_worker.h
)
