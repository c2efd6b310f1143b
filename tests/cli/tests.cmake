# The CLI front's own parts, without devices (paths relative to tests/).
# Issue 30, item 1: the devices of a machine taken per port.
cambench_add_test(tst_cli_machine_parallel SOURCES cli/tst_cli_machine_parallel.cpp
  LIBS cambench_cli_front)
