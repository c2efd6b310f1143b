cambench_add_test(cameditor_document_test SOURCES ui/register_widgets.cpp ui/cameditor/tst_cam_document.cpp ui/cameditor/cam_test_support.h LIBS cambench_ui cambench_gui_registry)
cambench_add_test(cameditor_widget_test SOURCES ui/register_widgets.cpp ui/cameditor/tst_cam_editor_widget.cpp ui/cameditor/cam_test_support.h LIBS cambench_ui cambench_gui_registry)
cambench_add_test(ui_shell_main_window_test SOURCES ui/register_widgets.cpp ui/shell/tst_main_window.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
cambench_add_test(ui_shell_pages_test SOURCES ui/register_widgets.cpp ui/shell/tst_shell_pages.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
