# The camcon family's GUI tests (paths relative to tests/).
cambench_add_test(ui_cambus_view_test SOURCES ui/register_widgets.cpp ui/camcon/tst_cambus_view.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
cambench_add_test(cameditor_document_test SOURCES ui/register_widgets.cpp ui/camcon/cameditor/tst_cam_document.cpp ui/camcon/cameditor/cam_test_support.h LIBS cambench_ui cambench_gui_registry)
cambench_add_test(cameditor_widget_test SOURCES ui/register_widgets.cpp ui/camcon/cameditor/tst_cam_editor_widget.cpp ui/camcon/cameditor/cam_test_support.h LIBS cambench_ui cambench_gui_registry)
# Issue 6 ("what CamBench says about a device must be true"): the GUI on
# real widgets against the simulator, one file per group of points.
function(cambench_add_truth_test name)
  cambench_add_test(${name} SOURCES ${ARGN} ui/register_widgets.cpp ui/camcon/truth/pty_simulator.h ui/shell/shell_fixture.h
                    LIBS cambench_ui cambench_gui_registry cambench_sim)
endfunction()
cambench_add_truth_test(ui_truth_write_test ui/camcon/truth/tst_write_truth.cpp)
cambench_add_truth_test(ui_truth_unwritten_edits_test ui/camcon/truth/tst_unwritten_edits.cpp)
cambench_add_truth_test(ui_truth_freshness_test ui/camcon/truth/tst_freshness.cpp)
cambench_add_truth_test(ui_truth_whole_device_test ui/camcon/truth/tst_whole_device.cpp)
cambench_add_truth_test(ui_truth_report_and_counts_test ui/camcon/truth/tst_report_and_counts.cpp)
cambench_add_truth_test(ui_truth_other_device_test ui/camcon/truth/tst_other_device.cpp)
cambench_add_truth_test(ui_shell_typed_port_test ui/camcon/truth/tst_typed_port.cpp)
cambench_add_test(ui_workspace_sections_test SOURCES ui/register_widgets.cpp ui/camcon/tst_workspace_sections.cpp LIBS cambench_ui cambench_gui_registry)
# Issue 38 item 3: a write report is applied by the key each outcome carries.
cambench_add_test(ui_write_pairing_test SOURCES ui/register_widgets.cpp ui/camcon/tst_write_pairing.cpp ui/camcon/cameditor/cam_test_support.h LIBS cambench_ui cambench_gui_registry)
