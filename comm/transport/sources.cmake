target_sources(cambench_comm PRIVATE
  transport/transport.h
  transport/transport_logging.h
  transport/transport_logging.cpp
  transport/serial_transport.h
  transport/serial_transport.cpp
  transport/tcp_transport.h
  transport/tcp_transport.cpp
  transport/transport_factory.h
  transport/transport_factory.cpp
)
