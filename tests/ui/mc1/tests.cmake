# The mc1 family's GUI tests (paths relative to tests/).
# Issue 14: the MC-1 pages against the simulated controller.
cambench_add_test(ui_mc1_pages_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/mc1/tst_mc1_pages.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
# Issue 27: typed stays typed, stale and paused, Set speed, jogging, trend, the kept watch list.
cambench_add_test(ui_mc1_live_pages_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/mc1/tst_mc1_live_pages.cpp ui/shell/shell_fixture.h ui/shell/live_value_checks.h LIBS cambench_ui cambench_gui_registry)
# Issue 27: the axes found, the axis parameter table (provisional or loaded), done vs read back.
cambench_add_test(ui_mc1_axes_parameters_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/mc1/tst_mc1_axes_parameters.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
# Issue 35 items 4 and 10: Escape in every dialog and menu stops a jogging axis; a STOP's report moves no button.
cambench_add_test(ui_mc1_stop_reach_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/mc1/tst_mc1_stop_reach.cpp ui/mc1/mc1_jog.h ui/shell/shell_fixture.h ui/shell/stop_reach_checks.h LIBS cambench_ui cambench_gui_registry)
# Issue 35: motion never waits in a queue (a jog during a backup is refused, never sent).
cambench_add_test(ui_mc1_motion_not_queued_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/mc1/tst_mc1_motion_not_queued.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
