# The protocol-neutral request engine: timeouts from the line, retries where
# they are safe, cancel, the traffic sink. Knows no protocol.
target_sources(cambench_comm PRIVATE
  engine/engine_logging.h
  engine/engine_logging.cpp
  engine/framing_backend.h
  engine/line_timing.h
  engine/request.h
  engine/cr_line_backend.h
  engine/cr_line_backend.cpp
  engine/request_engine.h
  engine/request_engine.cpp
  engine/between_requests.h
  engine/between_requests.cpp
  engine/stop_generation.h
  engine/stop_generation.cpp
)
