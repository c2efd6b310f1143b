target_sources(cambench_comm PRIVATE
  transport/transport.h
  transport/break_marks.h
  transport/break_marks.cpp
  transport/transport_logging.h
  transport/transport_logging.cpp
  transport/serial_transport.h
  transport/serial_transport.cpp
  transport/tcp_transport.h
  transport/tcp_transport.cpp
  transport/transport_registry.h
  transport/transport_registry.cpp
)
