# The compax3 family's GUI tests (paths relative to tests/).
cambench_add_test(ui_compax3_pages_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/compax3/tst_compax3_pages.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
# Issue 35 items 4 and 5: Escape in every dialog and menu stops a jogging drive; another RS485 address asks first.
cambench_add_test(ui_compax3_stop_reach_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/compax3/tst_compax3_stop_reach.cpp ui/shell/shell_fixture.h ui/shell/stop_reach_checks.h LIBS cambench_ui cambench_gui_registry)
