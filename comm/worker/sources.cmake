target_sources(cambench_comm PRIVATE
  worker/comm_worker.h
  worker/comm_worker.cpp
  worker/worker_logging.h
  worker/worker_logging.cpp
  worker/job_queue.h
  worker/job_queue.cpp
  worker/guarded_transport.h
  worker/guarded_transport.cpp
  worker/worker_core.h
  worker/worker_core.cpp
)
