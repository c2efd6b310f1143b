# The CLI front's own parts, without devices (paths relative to tests/).
# Issue 30, item 1: the devices of a machine taken per port.
cambench_add_test(tst_cli_machine_parallel SOURCES cli/tst_cli_machine_parallel.cpp
  LIBS cambench_cli_front)
# Issue 39, item 4: every option before or after the command, the family
# and protocol each word names, contradictions named.
cambench_add_test(tst_cli_options SOURCES cli/tst_cli_options.cpp LIBS cambench_cli_front)
