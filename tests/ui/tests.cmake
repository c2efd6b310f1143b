# The shell's GUI tests (tests/ui/shell/, paths relative to tests/); each
# family's are listed in its folder (tests/ui/<family>/tests.cmake).
# Issue 6: the shell's small faults, on the fake family.
cambench_add_test(ui_shell_small_faults_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_small_faults.cpp ui/shell/shell_fixture.h ui/shell/fake_shell_fixture.h LIBS cambench_ui cambench_gui_registry cambench_test_fake_family)
# Issue 38 item 4: the main window on the fake family (connection state, log, job progress).
cambench_add_test(ui_shell_main_window_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_main_window.cpp ui/shell/shell_fixture.h ui/shell/fake_shell_fixture.h LIBS cambench_ui cambench_gui_registry cambench_test_fake_family)
# Issue 13: the connection page's family choice and Detect on a pty.
cambench_add_test(ui_shell_detect_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_detect.cpp ui/shell/shell_fixture.h ui/shell/fake_shell_fixture.h LIBS cambench_ui cambench_gui_registry cambench_sim cambench_test_fake_family)
# Issue 27: the shell's poll cycle (stale after a missed cycle, paused behind a long job).
cambench_add_test(ui_shell_live_poll_cycle_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_live_poll_cycle.cpp ui/shell/shell_fixture.h ui/shell/fake_shell_fixture.h ui/shell/live_value_checks.h LIBS cambench_ui cambench_gui_registry cambench_test_fake_family)
# Issue 28 item 4: a family switch or another device leaves nothing of the one before.
cambench_add_test(ui_shell_family_switch_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_family_switch.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
# Issue 30: the machine window (several devices at once, STOP for all, the machine file).
cambench_add_test(ui_shell_machine_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_machine.cpp ui/shell/shell_fixture.h ui/shell/machine_fixture.h ui/shell/stop_reach_checks.h LIBS cambench_ui cambench_gui_registry)
# Issue 38 item 4: the machine window through two fake devices that differ.
cambench_add_test(ui_shell_machine_shell_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_machine_shell.cpp ui/shell/shell_fixture.h ui/shell/fake_shell_fixture.h ui/shell/machine_fixture.h ui/shell/history_fixture.h LIBS cambench_ui cambench_gui_registry cambench_test_fake_family)
# Issue 36 item 4: Machine -> Back up, Verify, Restore in the machine window.
cambench_add_test(ui_shell_machine_backup_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_machine_backup.cpp ui/shell/shell_fixture.h ui/shell/machine_fixture.h LIBS cambench_ui cambench_gui_registry)
# Issue 36 items 6 and 7: the right devices on ptys, every family's edits, one menu bar, columns.
cambench_add_test(ui_shell_machine_devices_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_machine_devices.cpp ui/shell/shell_fixture.h ui/shell/machine_fixture.h LIBS cambench_ui cambench_gui_registry cambench_sim)
# Issue 37: Machine → History… (versions compared, one marked released).
cambench_add_test(ui_shell_machine_history_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/shell/tst_machine_history.cpp ui/shell/shell_fixture.h ui/shell/history_fixture.h LIBS cambench_ui cambench_gui_registry)
# Each family's GUI tests, listed in its folder.
cambench_include_family_lists(${CMAKE_CURRENT_LIST_DIR} tests.cmake)
