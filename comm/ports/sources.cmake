# The serial ports this PC has, with what their adapters say of themselves.
target_sources(cambench_comm PRIVATE
  ports/serial_port_list.h
  ports/serial_port_list.cpp
)
