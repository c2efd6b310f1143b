# The camcon family's GUI tests (paths relative to tests/).
cambench_add_test(ui_cambus_view_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/camcon/tst_cambus_view.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
cambench_add_test(cameditor_document_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/camcon/cameditor/tst_cam_document.cpp ui/camcon/cameditor/cam_test_support.h LIBS cambench_ui cambench_gui_registry)
cambench_add_test(cameditor_widget_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/camcon/cameditor/tst_cam_editor_widget.cpp ui/camcon/cameditor/cam_test_support.h LIBS cambench_ui cambench_gui_registry)
# Issue 6 ("what CamBench says about a device must be true"): the GUI on
# real widgets against the simulator, one file per group of points.
function(cambench_add_truth_test name)
  cambench_add_test(${name} SOURCES ${ARGN} $<TARGET_OBJECTS:cambench_test_gui_check> ui/camcon/truth/pty_simulator.h ui/camcon/camcon_fixture.h ui/shell/shell_fixture.h
                    LIBS cambench_ui cambench_gui_registry cambench_sim)
endfunction()
cambench_add_truth_test(ui_truth_write_test ui/camcon/truth/tst_write_truth.cpp)
cambench_add_truth_test(ui_truth_unwritten_edits_test ui/camcon/truth/tst_unwritten_edits.cpp)
cambench_add_truth_test(ui_truth_freshness_test ui/camcon/truth/tst_freshness.cpp)
cambench_add_truth_test(ui_truth_whole_device_test ui/camcon/truth/tst_whole_device.cpp)
cambench_add_truth_test(ui_truth_report_and_counts_test ui/camcon/truth/tst_report_and_counts.cpp)
cambench_add_truth_test(ui_truth_other_device_test ui/camcon/truth/tst_other_device.cpp)
cambench_add_truth_test(ui_shell_typed_port_test ui/camcon/truth/tst_typed_port.cpp)
cambench_add_test(ui_workspace_sections_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/camcon/tst_workspace_sections.cpp LIBS cambench_ui cambench_gui_registry)
# The CamCon's pages, windows and workflows in the shell's window (moved
# from tests/ui/shell/, issue 38 item 4): real widgets on the in-process
# simulator through the real worker.
function(cambench_add_camcon_gui_test name source)
  cambench_add_test(${name} SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/camcon/${source} ui/camcon/camcon_fixture.h ui/shell/shell_fixture.h
                    LIBS cambench_ui cambench_gui_registry ${ARGN})
endfunction()
cambench_add_camcon_gui_test(ui_camcon_cam_page_test tst_cam_page.cpp)
cambench_add_camcon_gui_test(ui_camcon_compare_dialogs_test tst_compare_dialogs.cpp)
cambench_add_camcon_gui_test(ui_camcon_sections_test tst_sections.cpp)
cambench_add_camcon_gui_test(ui_camcon_backup_wizard_test tst_backup_wizard.cpp)
cambench_add_camcon_gui_test(ui_camcon_pages_test tst_camcon_pages.cpp)
cambench_add_camcon_gui_test(ui_camcon_small_faults_test tst_camcon_small_faults.cpp)
cambench_add_camcon_gui_test(ui_camcon_line_backup_test tst_line_backup.cpp)
# Issue 12, point 5: the PLC coupling page on a pty.
cambench_add_camcon_gui_test(ui_camcon_plc_coupling_test tst_plc_coupling.cpp cambench_sim)
# Issue 12, points 2 and 7: the table interface's own pages.
cambench_add_camcon_gui_test(ui_camcon_table_page_edits_test tst_table_page_edits.cpp)
# Issue 9, item 3: what the GUI remembers of a CamCon line, its project and
# its section survives a restart.
cambench_add_camcon_gui_test(ui_camcon_gui_settings_test tst_gui_settings.cpp)
# Issue 38 item 3: a write report is applied by the key each outcome carries.
cambench_add_test(ui_write_pairing_test SOURCES $<TARGET_OBJECTS:cambench_test_gui_check> ui/camcon/tst_write_pairing.cpp ui/camcon/cameditor/cam_test_support.h LIBS cambench_ui cambench_gui_registry)
